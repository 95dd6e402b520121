#include "runner/live/lcm_message_bounds.h"

#include <cstdint>

namespace areagraph {
namespace {

// LCM's type fingerprint in front of every message.
constexpr int kFingerprintBytes = 8;

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

  // area_t: id, kind, outer, holes, area_m2, centroid, passage_ids.
  void SkipArea() {
    Skip(4 + 1);
    SkipRing();
    const int32_t holes = Count(4);
    for (int32_t h = 0; ok_ && h < holes; ++h) SkipRing();
    Skip(3 * 8);
    Skip(int64_t{Count(4)} * 4);
  }

  // What area_graph_t and area_graph_diff_t start with: the fingerprint,
  // map_name, artifact_key, version and predecessor_key.
  void SkipGraphIdentity() {
    Skip(kFingerprintBytes);
    SkipString();  // map_name
    SkipString();  // artifact_key
    Skip(8);       // version
    SkipString();  // predecessor_key
  }

  // A count and that many passage_t: three int32 ids, seven doubles, and the
  // border (num_border_points, border_x[], border_y[]).
  void SkipPassages() {
    constexpr int kPassageFixedBytes = 3 * 4 + 7 * 8;
    const int32_t passages = Count(kPassageFixedBytes + 4);
    for (int32_t i = 0; ok_ && i < passages; ++i) {
      Skip(kPassageFixedBytes);
      SkipRing();
    }
  }

 private:
  const uint8_t* data_;
  int size_;
  int position_ = 0;
  bool ok_ = true;
};

// area_t without its arrays' elements: id, kind, outer ring count, num_holes,
// area and centroid, num_passages.
constexpr int kAreaMinBytes = 4 + 1 + 4 + 4 + 3 * 8 + 4;

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
  bytes.SkipGraphIdentity();
  bytes.Skip(3 * 8);          // utime, sequence, map_utime
  bytes.Skip(4 * 8 + 2 * 4);  // resolution, origin, width_px, height_px
  const int32_t areas = bytes.Count(kAreaMinBytes);
  for (int32_t i = 0; bytes.ok() && i < areas; ++i) bytes.SkipArea();
  bytes.SkipPassages();
  return bytes.ok() ? bytes.position() : -1;
}

int AreaGraphDiffEncodedSize(const void* data, int size) {
  EncodedBytes bytes(data, size);
  bytes.SkipGraphIdentity();
  bytes.Skip(4 * 8);  // predecessor_version, utime, sequence, map_utime
  const int32_t added = bytes.Count(kAreaMinBytes);
  for (int32_t i = 0; bytes.ok() && i < added; ++i) bytes.SkipArea();
  bytes.Skip(int64_t{bytes.Count(4)} * 4);  // removed_area_ids
  const int32_t changed = bytes.Count(1 + kAreaMinBytes + 2 * 4);
  for (int32_t i = 0; bytes.ok() && i < changed; ++i) {
    bytes.Skip(1);  // changes
    bytes.SkipArea();
    bytes.Skip(int64_t{bytes.Count(4)} * 4);  // split_into
    bytes.Skip(int64_t{bytes.Count(4)} * 4);  // merged_from
  }
  bytes.Skip(4);  // unchanged_areas
  bytes.SkipPassages();
  bytes.Skip(int64_t{bytes.Count(4)} * 4);  // removed_passage_ids
  bytes.SkipPassages();
  bytes.Skip(4);  // unchanged_passages
  return bytes.ok() ? bytes.position() : -1;
}

}  // namespace areagraph
