// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_png.h
/// A dependency-free PNG writer (8-bit RGB, uncompressed deflate blocks) for plots and pictures.
#ifndef SHAPECORR_IO_WRITE_PNG_H
#define SHAPECORR_IO_WRITE_PNG_H

#include <shapecorr/exceptions.h>

#include <array>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// An RGB picture, row-major, row 0 on top.
struct Rgb_picture {
  std::size_t width = 0, height = 0;
  std::vector<std::uint8_t> rgb; // 3 bytes per pixel
  Rgb_picture() = default;
  Rgb_picture(std::size_t w, std::size_t h, std::array<std::uint8_t, 3> fill = {{255, 255, 255}}) : width(w), height(h), rgb(3 * w * h) {
    for(std::size_t i = 0; i < w * h; ++i)
      for(int c = 0; c < 3; ++c) rgb[3 * i + static_cast<std::size_t>(c)] = fill[static_cast<std::size_t>(c)];
  }
  void set(std::size_t x, std::size_t y, std::array<std::uint8_t, 3> c) {
    if(x >= width || y >= height) return;
    for(int k = 0; k < 3; ++k) rgb[3 * (y * width + x) + static_cast<std::size_t>(k)] = c[static_cast<std::size_t>(k)];
  }
};

namespace internal {
inline std::uint32_t crc32(const std::uint8_t* p, std::size_t n, std::uint32_t crc = 0) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for(std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for(int k = 0; k < 8; ++k) c = (c & 1) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  crc = ~crc;
  for(std::size_t i = 0; i < n; ++i) crc = table[(crc ^ p[i]) & 0xFFu] ^ (crc >> 8);
  return ~crc;
}
inline void put_u32(std::vector<std::uint8_t>& v, std::uint32_t x) {
  for(int s = 24; s >= 0; s -= 8) v.push_back(static_cast<std::uint8_t>((x >> s) & 0xFFu));
}
inline void png_chunk(std::ofstream& out, const char* type, const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> buf;
  put_u32(buf, static_cast<std::uint32_t>(data.size()));
  std::vector<std::uint8_t> body(type, type + 4);
  body.insert(body.end(), data.begin(), data.end());
  buf.insert(buf.end(), body.begin(), body.end());
  put_u32(buf, crc32(body.data(), body.size()));
  out.write(reinterpret_cast<const char*>(buf.data()), static_cast<std::streamsize>(buf.size()));
}
} // namespace internal

/// \ingroup PkgShapeCorrIO
/// Writes `pic` as a PNG file (zlib stream of stored blocks: larger than a compressed PNG, read by
/// every viewer).
/// \throws Invalid_input (`unreadable_file`) when the file cannot be written or the picture is empty
inline void write_png(const std::string& path, const Rgb_picture& pic) {
  if(pic.width == 0 || pic.height == 0 || pic.rgb.size() != 3 * pic.width * pic.height)
    throw Invalid_input(Mesh_defect::invalid_argument, "write_png: empty or inconsistent picture");
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Invalid_input(Mesh_defect::unreadable_file, "write_png: cannot write '" + path + "'");
  static const std::uint8_t signature[8] = {137, 80, 78, 71, 13, 10, 26, 10};
  out.write(reinterpret_cast<const char*>(signature), 8);
  std::vector<std::uint8_t> ihdr;
  internal::put_u32(ihdr, static_cast<std::uint32_t>(pic.width));
  internal::put_u32(ihdr, static_cast<std::uint32_t>(pic.height));
  ihdr.insert(ihdr.end(), {8, 2, 0, 0, 0}); // 8 bits, RGB, deflate, no filter method, no interlace
  internal::png_chunk(out, "IHDR", ihdr);
  std::vector<std::uint8_t> raw; // filter byte 0 + row
  raw.reserve(pic.height * (1 + 3 * pic.width));
  for(std::size_t y = 0; y < pic.height; ++y) {
    raw.push_back(0);
    raw.insert(raw.end(), pic.rgb.begin() + static_cast<std::ptrdiff_t>(3 * pic.width * y),
               pic.rgb.begin() + static_cast<std::ptrdiff_t>(3 * pic.width * (y + 1)));
  }
  std::vector<std::uint8_t> z = {0x78, 0x01};
  for(std::size_t pos = 0; pos < raw.size() || pos == 0; pos += 65535) {
    const std::size_t len = std::min<std::size_t>(65535, raw.size() - pos);
    z.push_back(pos + len >= raw.size() ? 1 : 0);
    z.push_back(static_cast<std::uint8_t>(len & 0xFF));
    z.push_back(static_cast<std::uint8_t>(len >> 8));
    z.push_back(static_cast<std::uint8_t>(~len & 0xFF));
    z.push_back(static_cast<std::uint8_t>((~len >> 8) & 0xFF));
    z.insert(z.end(), raw.begin() + static_cast<std::ptrdiff_t>(pos), raw.begin() + static_cast<std::ptrdiff_t>(pos + len));
    if(len == 0) break;
  }
  std::uint32_t a = 1, b = 0; // Adler-32
  for(std::uint8_t c : raw) {
    a = (a + c) % 65521u;
    b = (b + a) % 65521u;
  }
  internal::put_u32(z, (b << 16) | a);
  internal::png_chunk(out, "IDAT", z);
  internal::png_chunk(out, "IEND", {});
  if(!out) throw Invalid_input(Mesh_defect::unreadable_file, "write_png: writing '" + path + "' failed");
}

} // namespace shapecorr

#endif
