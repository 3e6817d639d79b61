// SHA-256 (FIPS 180-4) of bytes and of files: the contents of a run's input files (section
// profiles, COR tables, options files) in its run record and in a sweep's resume signature,
// so that an edited table is noticed whatever its path. Self-contained (no OpenSSL).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace beamimpact {

// Incremental SHA-256: Update with the bytes in order, then HexDigest (64 lowercase hex digits).
class Sha256 {
public:
  Sha256();
  void        Update(const void *data, size_t n);
  std::string HexDigest(); // ends the computation
private:
  void          Block(const unsigned char *p);
  uint32_t      h_[8];
  uint64_t      bytes_ = 0;
  unsigned char buf_[64];
  size_t        fill_ = 0;
};

std::string Sha256Hex(const std::string &bytes);

// The SHA-256 of the file at path; false (digest empty) when it cannot be read.
bool Sha256File(const std::string &path, std::string *digest);

} // namespace beamimpact
