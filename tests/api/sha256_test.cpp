// SHA-256 against the FIPS 180-2 test vectors.
#include "api/job_spec.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

using slipfront::api::sha256_file;
using slipfront::api::sha256_hex;

TEST(Sha256, KnownVectors) {
  EXPECT_EQ(sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST(Sha256, FileDigestEqualsDigestOfItsBytes) {
  const std::string path = ::testing::TempDir() + "sha256_test.bin";
  std::string bytes;
  for (int i = 0; i < 3'000'000; ++i)
    bytes += static_cast<char>(i * 7 % 256); // > one buffer
  std::ofstream(path, std::ios::binary) << bytes;
  EXPECT_EQ(sha256_file(path), sha256_hex(bytes));
  std::remove(path.c_str());
}

TEST(Sha256, MissingFileThrows) {
  EXPECT_THROW(sha256_file("/nonexistent/slipfront/file"), std::runtime_error);
}
