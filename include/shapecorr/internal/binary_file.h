// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the checked binary files of the value classes (the eigenbasis, the statistical shape
// model): an 8-byte magic, a byte-order mark, the data in native byte order, and the 64-bit FNV-1a
// checksum of everything before it. The reader checks each count against the bytes left before it
// allocates, so a corrupt or hostile size cannot make it allocate more than the file holds.
#ifndef SHAPECORR_INTERNAL_BINARY_FILE_H
#define SHAPECORR_INTERNAL_BINARY_FILE_H

#include <shapecorr/exceptions.h>

#include <cstdint>
#include <fstream>
#include <functional>
#include <string>

namespace shapecorr {
namespace internal {

constexpr std::uint32_t binary_byte_order_mark = 0x01020304u;

inline std::uint64_t fnv1a(std::uint64_t h, const void* data, std::uint64_t bytes) {
  const unsigned char* p = static_cast<const unsigned char*>(data);
  for(std::uint64_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
  return h;
}
constexpr std::uint64_t fnv_offset = 14695981039346656037ull;

/// Writes `magic` (8 bytes) and the byte-order mark; `put` adds data to the file and the checksum;
/// `finish` writes the checksum. Errors: `Output_error` naming `what` and the path.
class Checked_binary_writer {
public:
  Checked_binary_writer(const std::string& path, const char* magic, const std::string& what) : m_out(path, std::ios::binary), m_path(path), m_what(what) {
    if(!m_out) throw Output_error(m_what + ": cannot write '" + m_path + "'");
    put(magic, 8);
    put(&binary_byte_order_mark, sizeof binary_byte_order_mark);
  }
  void put(const void* data, std::uint64_t bytes) {
    m_out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
    m_hash = fnv1a(m_hash, data, bytes);
  }
  void put_u64(std::uint64_t v) { put(&v, sizeof v); }
  void put_double(double v) { put(&v, sizeof v); }
  void finish() {
    m_out.write(reinterpret_cast<const char*>(&m_hash), sizeof m_hash);
    m_out.flush();
    if(!m_out) throw Output_error(m_what + ": writing '" + m_path + "' failed");
  }

private:
  std::ofstream m_out;
  std::string m_path, m_what;
  std::uint64_t m_hash = fnv_offset;
};

/// Reads a file written by `Checked_binary_writer`: the constructor checks the magic's first
/// `magic_prefix` bytes (the kind of file; the rest is its version, returned by `version()`) and
/// the byte order. `get` reads bytes (throwing "truncated" past the data), `require` checks that a
/// count of items of a size fits in the bytes left, `finish` checks that the checksum follows and
/// matches. Errors: `Invalid_input` (`unreadable_file`) naming `what` and the path.
class Checked_binary_reader {
public:
  Checked_binary_reader(const std::string& path, const char* magic, std::size_t magic_prefix, const std::string& what) : m_path(path), m_what(what) {
    m_in.open(path, std::ios::binary);
    if(!m_in) fail("cannot open the file");
    m_in.seekg(0, std::ios::end);
    const std::streamoff end = m_in.tellg();
    if(end < 0) fail("cannot determine the file size (not a regular file?)");
    m_in.seekg(0);
    const std::uint64_t size = static_cast<std::uint64_t>(end);
    m_left = size;
    if(size >= 8) get(m_magic, 8);
    if(size < 8 || std::string(m_magic, magic_prefix) != std::string(magic, magic_prefix)) fail("not a ShapeCorr " + m_what + " file");
    if(size < 8 + 4 + 8) fail("truncated: " + std::to_string(size) + " bytes, shorter than any " + m_what + " file");
    m_left -= 8; // the checksum is not data
    std::uint32_t order = 0;
    get(&order, sizeof order);
    if(order != binary_byte_order_mark) fail("written on a machine of the other byte order");
  }
  /// The magic's bytes after the prefix (the format version).
  std::string version(std::size_t magic_prefix) const { return std::string(m_magic + magic_prefix, 8 - magic_prefix); }
  [[noreturn]] void fail(const std::string& why) const { throw Invalid_input(Mesh_defect::unreadable_file, m_what + ": '" + m_path + "': " + why); }
  /// Throws unless `count` items of `item_bytes` each fit in the data left (`what`: which items).
  void require(std::uint64_t count, std::uint64_t item_bytes, const std::string& what) const {
    if(item_bytes != 0 && count > m_left / item_bytes)
      fail("the sizes disagree with the file size: " + std::to_string(count) + " " + what + " do not fit in the " + std::to_string(m_left) + " bytes left");
  }
  void get(void* data, std::uint64_t bytes) {
    if(bytes > m_left) fail("truncated");
    m_in.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
    if(!m_in) fail("truncated");
    m_hash = fnv1a(m_hash, data, bytes);
    m_left -= bytes;
  }
  std::uint64_t get_u64() {
    std::uint64_t v = 0;
    get(&v, sizeof v);
    return v;
  }
  double get_double() {
    double v = 0;
    get(&v, sizeof v);
    return v;
  }
  std::uint64_t bytes_left() const { return m_left; }
  void finish() {
    if(m_left != 0) fail("the sizes disagree with the file size (" + std::to_string(m_left) + " bytes left over)");
    std::uint64_t stored = 0;
    m_in.read(reinterpret_cast<char*>(&stored), sizeof stored);
    if(!m_in) fail("truncated");
    if(stored != m_hash) fail("checksum mismatch (the file is corrupt)");
  }

private:
  std::ifstream m_in;
  std::string m_path, m_what;
  char m_magic[8] = {0};
  std::uint64_t m_left = 0;
  std::uint64_t m_hash = fnv_offset;
};

} // namespace internal
} // namespace shapecorr

#endif
