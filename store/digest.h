#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace areagraph {

// Lower-case hex SHA-256 of `bytes` (nettle).
std::string Sha256Hex(std::string_view bytes);

// Incremental SHA-256 for data that arrives in pieces.
class Sha256 {
 public:
  Sha256();
  ~Sha256();
  Sha256(const Sha256&) = delete;
  Sha256& operator=(const Sha256&) = delete;
  void Update(std::string_view bytes);
  std::string FinishHex();

 private:
  void* ctx_;
};

}  // namespace areagraph
