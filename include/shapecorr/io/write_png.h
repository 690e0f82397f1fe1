// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_png.h
/// A dependency-free PNG writer (8-bit RGB, deflate-compressed) for plots and pictures.
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
  std::size_t width = 0;         ///< pixels per row
  std::size_t height = 0;        ///< rows
  std::vector<std::uint8_t> rgb; ///< 3 bytes (red, green, blue) per pixel, row-major
  Rgb_picture() = default;
  /// A w x h picture filled with `fill`.
  Rgb_picture(std::size_t w, std::size_t h, std::array<std::uint8_t, 3> fill = {{255, 255, 255}}) : width(w), height(h), rgb(3 * w * h) {
    for(std::size_t i = 0; i < w * h; ++i)
      for(int c = 0; c < 3; ++c) rgb[3 * i + static_cast<std::size_t>(c)] = fill[static_cast<std::size_t>(c)];
  }
  /// Sets pixel (x, y) (x to the right, y downwards) to colour c; ignored outside the picture.
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

namespace internal {
// Deflate (RFC 1951) with greedy LZ77 matching (hash chains, 32 KiB window) and the fixed Huffman
// codes: plots and pictures with large flat areas shrink 20-100x.
class Deflate_writer {
public:
  explicit Deflate_writer(std::vector<std::uint8_t>& out) : m_out(out) {}
  void bits(std::uint32_t value, int count) { // LSB first
    for(int i = 0; i < count; ++i) {
      m_acc |= ((value >> i) & 1u) << m_n;
      if(++m_n == 8) flush_byte();
    }
  }
  void huffman(std::uint32_t code, int len) { // Huffman codes go MSB first
    for(int i = len - 1; i >= 0; --i) bits((code >> i) & 1u, 1);
  }
  void literal(std::uint32_t v) {
    if(v < 144) huffman(0x30 + v, 8);
    else if(v < 256) huffman(0x190 + v - 144, 9);
    else if(v < 280) huffman(v - 256, 7);
    else huffman(0xC0 + v - 280, 8);
  }
  void match(std::uint32_t length, std::uint32_t distance) {
    static const std::uint16_t lbase[29] = {3, 4, 5, 6, 7, 8, 9, 10, 11, 13, 15, 17, 19, 23, 27, 31, 35, 43, 51, 59, 67, 83, 99, 115, 131, 163, 195, 227, 258};
    static const std::uint8_t lextra[29] = {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2, 3, 3, 3, 3, 4, 4, 4, 4, 5, 5, 5, 5, 0};
    static const std::uint16_t dbase[30] = {1, 2, 3, 4, 5, 7, 9, 13, 17, 25, 33, 49, 65, 97, 129, 193, 257, 385, 513, 769, 1025, 1537, 2049, 3073, 4097, 6145, 8193, 12289, 16385, 24577};
    static const std::uint8_t dextra[30] = {0, 0, 0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 7, 7, 8, 8, 9, 9, 10, 10, 11, 11, 12, 12, 13, 13};
    int l = 28;
    while(lbase[l] > length) --l;
    literal(257 + static_cast<std::uint32_t>(l));
    bits(length - lbase[l], lextra[l]);
    int d = 29;
    while(dbase[d] > distance) --d;
    huffman(static_cast<std::uint32_t>(d), 5);
    bits(distance - dbase[d], dextra[d]);
  }
  void finish() {
    if(m_n) flush_byte();
  }

private:
  void flush_byte() {
    m_out.push_back(static_cast<std::uint8_t>(m_acc));
    m_acc = 0;
    m_n = 0;
  }
  std::vector<std::uint8_t>& m_out;
  std::uint32_t m_acc = 0;
  int m_n = 0;
};

inline void deflate_fixed(const std::vector<std::uint8_t>& in, std::vector<std::uint8_t>& out) {
  Deflate_writer w(out);
  w.bits(1, 1); // final block
  w.bits(1, 2); // fixed Huffman codes
  const std::size_t n = in.size(), window = 32768, max_chain = 64;
  std::vector<std::int64_t> head(1u << 15, -1), prev(n, -1);
  auto hash = [&](std::size_t i) { return ((static_cast<std::uint32_t>(in[i]) << 10) ^ (static_cast<std::uint32_t>(in[i + 1]) << 5) ^ in[i + 2]) & 0x7FFFu; };
  auto insert = [&](std::size_t i) {
    if(i + 2 >= n) return;
    const std::uint32_t h = hash(i);
    prev[i] = head[h];
    head[h] = static_cast<std::int64_t>(i);
  };
  std::size_t i = 0;
  while(i < n) {
    std::size_t best = 0, dist = 0;
    if(i + 2 < n) {
      std::int64_t j = head[hash(i)];
      for(std::size_t chain = 0; j >= 0 && i - static_cast<std::size_t>(j) <= window && chain < max_chain; ++chain, j = prev[static_cast<std::size_t>(j)]) {
        const std::size_t s = static_cast<std::size_t>(j);
        std::size_t len = 0;
        while(len < 258 && i + len < n && in[s + len] == in[i + len]) ++len;
        if(len > best) {
          best = len;
          dist = i - s;
          if(len == 258) break;
        }
      }
    }
    if(best >= 3) {
      w.match(static_cast<std::uint32_t>(best), static_cast<std::uint32_t>(dist));
      for(std::size_t k = 0; k < best; ++k) insert(i + k);
      i += best;
    } else {
      w.literal(in[i]);
      insert(i);
      ++i;
    }
  }
  w.literal(256); // end of block
  w.finish();
}
} // namespace internal

/// \ingroup PkgShapeCorrIO
/// Writes `pic` as a PNG file (deflate with fixed Huffman codes; no external library).
/// \throws Output_error when the file cannot be written; Invalid_argument when the picture is empty
inline void write_png(const std::string& path, const Rgb_picture& pic) {
  if(pic.width == 0 || pic.height == 0 || pic.rgb.size() != 3 * pic.width * pic.height)
    throw Invalid_argument("write_png: empty or inconsistent picture");
  std::ofstream out(path, std::ios::binary);
  if(!out) throw Output_error("write_png: cannot write '" + path + "'");
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
  internal::deflate_fixed(raw, z);
  std::uint32_t a = 1, b = 0; // Adler-32
  for(std::uint8_t c : raw) {
    a = (a + c) % 65521u;
    b = (b + a) % 65521u;
  }
  internal::put_u32(z, (b << 16) | a);
  internal::png_chunk(out, "IDAT", z);
  internal::png_chunk(out, "IEND", {});
  if(!out) throw Output_error("write_png: writing '" + path + "' failed");
}

} // namespace shapecorr

#endif
