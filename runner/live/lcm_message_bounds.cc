#include "runner/live/lcm_message_bounds.h"

#include <cstdint>

namespace areagraph {
namespace {

// A cursor over LCM's big-endian encoding that fails (ok() == false) instead
// of reading past the end.
class EncodedBytes {
 public:
  EncodedBytes(const void* data, int size)
      : data_(static_cast<const uint8_t*>(data)), size_(size) {}

  bool ok() const { return ok_; }
  int position() const { return position_; }

  void Skip(int64_t bytes) {
    if (!ok_ || bytes < 0 || bytes > size_ - position_) {
      ok_ = false;
      return;
    }
    position_ += static_cast<int>(bytes);
  }

  // A non-negative count whose elements, each at least `min_element_bytes`
  // long, can still fit in the rest of the message; -1 otherwise.
  int32_t Count(int min_element_bytes) {
    if (!ok_ || size_ - position_ < 4) {
      ok_ = false;
      return -1;
    }
    const uint8_t* p = data_ + position_;
    const int32_t count = static_cast<int32_t>((uint32_t{p[0]} << 24) | (uint32_t{p[1]} << 16) |
                                               (uint32_t{p[2]} << 8) | uint32_t{p[3]});
    position_ += 4;
    if (count < 0 || int64_t{count} * min_element_bytes > size_ - position_) {
      ok_ = false;
      return -1;
    }
    return count;
  }

  // An LCM string: int32 length including the terminating NUL, then bytes.
  void SkipString() {
    const int32_t length = Count(1);
    if (length < 1) ok_ = false;
    Skip(length);
  }

  // ring_t (num_points, x[num_points], y[num_points]), or any such point list.
  void SkipRing() { Skip(int64_t{Count(16)} * 16); }

 private:
  const uint8_t* data_;
  int size_;
  int position_ = 0;
  bool ok_ = true;
};

constexpr int kFingerprintBytes = 8;
constexpr int kRingMinBytes = 4;
// area_t without its arrays' elements: id, kind, outer ring count, num_holes,
// area and centroid, num_passages.
constexpr int kAreaMinBytes = 4 + 1 + 4 + 4 + 3 * 8 + 4;
// passage_t without its border's points: three int32 ids, seven doubles and
// num_border_points.
constexpr int kPassageFixedBytes = 3 * 4 + 7 * 8;
constexpr int kPassageMinBytes = kPassageFixedBytes + 4;

}  // namespace

int GridMapEncodedSize(const void* data, int size) {
  EncodedBytes bytes(data, size);
  bytes.Skip(kFingerprintBytes);
  bytes.Skip(8 + 4 * 8 + 2 * 4);  // utime, resolution, origin, width, height
  bytes.Skip(bytes.Count(1));     // cells
  bytes.SkipString();             // name
  return bytes.ok() ? bytes.position() : -1;
}

int AreaGraphEncodedSize(const void* data, int size) {
  EncodedBytes bytes(data, size);
  bytes.Skip(kFingerprintBytes);
  bytes.SkipString();         // map_name
  bytes.SkipString();         // artifact_key
  bytes.Skip(4 * 8 + 2 * 4);  // resolution, origin, width_px, height_px
  const int32_t areas = bytes.Count(kAreaMinBytes);
  for (int32_t i = 0; bytes.ok() && i < areas; ++i) {
    bytes.Skip(4 + 1);  // id, kind
    bytes.SkipRing();   // outer
    const int32_t holes = bytes.Count(kRingMinBytes);
    for (int32_t h = 0; bytes.ok() && h < holes; ++h) bytes.SkipRing();
    bytes.Skip(3 * 8);                        // area_m2, centroid
    bytes.Skip(int64_t{bytes.Count(4)} * 4);  // passage_ids
  }
  const int32_t passages = bytes.Count(kPassageMinBytes);
  for (int32_t i = 0; bytes.ok() && i < passages; ++i) {
    bytes.Skip(kPassageFixedBytes);
    bytes.SkipRing();  // border: num_border_points, border_x[], border_y[]
  }
  return bytes.ok() ? bytes.position() : -1;
}

}  // namespace areagraph
