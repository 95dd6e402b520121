#include "store/digest.h"

#include <nettle/sha2.h>

namespace areagraph {
namespace {

sha256_ctx* Ctx(void* p) { return static_cast<sha256_ctx*>(p); }

std::string ToHex(const uint8_t* bytes, size_t size) {
  static const char kHex[] = "0123456789abcdef";
  std::string hex(size * 2, '0');
  for (size_t i = 0; i < size; ++i) {
    hex[2 * i] = kHex[bytes[i] >> 4];
    hex[2 * i + 1] = kHex[bytes[i] & 0xf];
  }
  return hex;
}

}  // namespace

// Nettle's SHA-256 (Debian's nettle-dev; the same digests as OpenSSL's, so
// the store's keys and payload checks do not change). OpenSSL 3 reaches its
// SHA-256 only through the provider machinery: initialising it and one
// EVP_MD_fetch were 3.5 M instructions and about 2 ms of a 25-ms ag-render
// (docs/performance.md, "Start-up"). Nettle's context is plain
// memory and it picks the SHA-NI code on CPUs that have it, as OpenSSL did.
Sha256::Sha256() : ctx_(new sha256_ctx) { sha256_init(Ctx(ctx_)); }

Sha256::~Sha256() { delete Ctx(ctx_); }

void Sha256::Update(std::string_view bytes) {
  sha256_update(Ctx(ctx_), bytes.size(), reinterpret_cast<const uint8_t*>(bytes.data()));
}

std::string Sha256::FinishHex() {
  uint8_t digest[SHA256_DIGEST_SIZE];
  sha256_digest(Ctx(ctx_), SHA256_DIGEST_SIZE, digest);
  return ToHex(digest, SHA256_DIGEST_SIZE);
}

std::string Sha256Hex(std::string_view bytes) {
  Sha256 sha;
  sha.Update(bytes);
  return sha.FinishHex();
}

}  // namespace areagraph
