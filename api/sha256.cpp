// SHA-256 through OpenSSL's EVP interface.
#include "api/job_spec.hpp"

#include <openssl/evp.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace slipfront::api {

namespace {

using DigestContext = std::unique_ptr<EVP_MD_CTX, decltype(&EVP_MD_CTX_free)>;

DigestContext new_sha256_context() {
  DigestContext context(EVP_MD_CTX_new(), &EVP_MD_CTX_free);
  if (!context || EVP_DigestInit_ex(context.get(), EVP_sha256(), nullptr) != 1) {
    throw std::runtime_error("SHA-256: cannot initialise the OpenSSL digest");
  }
  return context;
}

void update(EVP_MD_CTX* context, const char* data, std::size_t size) {
  if (EVP_DigestUpdate(context, data, size) != 1) {
    throw std::runtime_error("SHA-256: digest update failed");
  }
}

std::string final_hex(EVP_MD_CTX* context) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> digest{};
  unsigned int length = 0;
  if (EVP_DigestFinal_ex(context, digest.data(), &length) != 1) {
    throw std::runtime_error("SHA-256: digest finalisation failed");
  }
  static constexpr char hex[] = "0123456789abcdef";
  std::string out;
  for (unsigned int i = 0; i < length; ++i) {
    out += hex[digest[i] >> 4];
    out += hex[digest[i] & 0xf];
  }
  return out;
}

} // namespace

std::string sha256_hex(std::string_view bytes) {
  DigestContext context = new_sha256_context();
  update(context.get(), bytes.data(), bytes.size());
  return final_hex(context.get());
}

std::string sha256_file(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw std::runtime_error("SHA-256: cannot open " + path);
  DigestContext context = new_sha256_context();
  std::vector<char> buffer(1 << 20);
  while (file) {
    file.read(buffer.data(), static_cast<std::streamsize>(buffer.size()));
    update(context.get(), buffer.data(), static_cast<std::size_t>(file.gcount()));
  }
  if (file.bad()) throw std::runtime_error("SHA-256: cannot read " + path);
  return final_hex(context.get());
}

std::string sha256_descriptor(int fd) {
  DigestContext context = new_sha256_context();
  std::vector<char> buffer(1 << 20);
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("SHA-256: cannot read: ") + std::strerror(errno));
    }
    update(context.get(), buffer.data(), static_cast<std::size_t>(n));
  }
  return final_hex(context.get());
}

} // namespace slipfront::api
