#include "io/checksum.hpp"

#include <cstdint>
#include <fstream>

#include "io/format.hpp"

namespace dlpverify {

std::string file_checksum(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return "unknown";
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a: offset basis, then xor and multiply by the prime
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    for (std::streamsize i = 0; i < in.gcount(); ++i) {
      hash ^= static_cast<unsigned char>(buffer[i]);
      hash *= 1099511628211ull;
    }
  if (in.bad()) return "unknown";
  return printf_string("%016llx", static_cast<unsigned long long>(hash));
}

}  // namespace dlpverify
