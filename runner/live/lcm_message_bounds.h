#pragma once

namespace areagraph {

// lcm-gen's decoders resize each array to the count read from the message
// before checking that the bytes are there, so a forged count makes them
// allocate gigabytes. These walk the encoded layout of the .lcm types in
// proto/ (fingerprint included) and return the message's encoded size when
// every count is non-negative and fits in the bytes that follow, or -1.
// They must follow the field order of the .lcm files; tests check them
// against getEncodedSize().
int GridMapEncodedSize(const void* data, int size);
int AreaGraphEncodedSize(const void* data, int size);
int AreaGraphDiffEncodedSize(const void* data, int size);

}  // namespace areagraph
