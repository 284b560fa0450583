// A minimal PNG writer (ISO/IEC 15948): 8-bit RGB, no interlacing, every row with filter type
// 0, the zlib stream (RFC 1950) made of stored (uncompressed) deflate blocks (RFC 1951, section
// 3.2.4) with its Adler-32, each chunk with its CRC-32. Large (about the raw size) but exact,
// and readable by every decoder.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace png {

// Writes `rgb` (width * height * 3 bytes, rows from the top) to `path`. Returns false and sets
// `error` on an I/O failure or inconsistent sizes.
bool write_rgb(const std::string &path, uint32_t width, uint32_t height,
               const std::vector<uint8_t> &rgb, std::string &error);

// The CRC-32 of ISO 3309 / ITU-T V.42 (the one PNG chunks carry) and the Adler-32 of zlib,
// exposed for the self-check.
uint32_t crc32(const uint8_t *data, size_t len, uint32_t crc = 0);
uint32_t adler32(const uint8_t *data, size_t len);

} // namespace png
