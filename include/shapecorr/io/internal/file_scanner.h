// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The pieces the strict mesh readers share: the whole file in memory, lines and tokens of text,
// numbers parsed without undefined behaviour, and one error with the place it happened.
#ifndef SHAPECORR_IO_INTERNAL_FILE_SCANNER_H
#define SHAPECORR_IO_INTERNAL_FILE_SCANNER_H

#include <shapecorr/exceptions.h>

#include <cerrno>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace shapecorr {
namespace internal {

/// A malformed file: `Invalid_input(unreadable_file, "PATH: WHERE: WHAT")`.
[[noreturn]] inline void malformed(const std::string& path, const std::string& where, const std::string& what) {
  throw Invalid_input(Mesh_defect::unreadable_file, path + ": " + (where.empty() ? "" : where + ": ") + what);
}

inline std::string line_place(std::size_t line) { return "line " + std::to_string(line); }
inline std::string byte_place(std::size_t offset) { return "byte " + std::to_string(offset); }

/// The bytes of a regular file. Refuses directories, devices and empty files with their own
/// messages; the file size bounds everything the readers allocate.
inline std::string read_file_bytes(const std::string& path) {
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if(ec || !std::filesystem::exists(status)) malformed(path, "", "cannot open the file (no such file)");
  if(std::filesystem::is_directory(status)) malformed(path, "", "is a directory, not a mesh file");
  if(!std::filesystem::is_regular_file(status)) malformed(path, "", "is not a regular file");
  std::ifstream in(path, std::ios::binary);
  if(!in) malformed(path, "", "cannot open the file (permission denied?)");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if(size < 0) malformed(path, "", "cannot determine the file size");
  if(size == 0) malformed(path, "", "the file is empty (0 bytes)");
  in.seekg(0, std::ios::beg);
  std::string bytes(static_cast<std::size_t>(size), '\0');
  in.read(&bytes[0], size);
  if(in.gcount() != size) malformed(path, "", "reading the file failed after " + std::to_string(in.gcount()) + " bytes");
  return bytes;
}

/// A printable rendering of a token for messages (at most 24 characters, bytes outside ASCII as \xNN).
inline std::string quoted(std::string_view token) {
  std::string o = "'";
  static const char* hex = "0123456789abcdef";
  for(std::size_t i = 0; i < token.size() && i < 24; ++i) {
    const unsigned char c = static_cast<unsigned char>(token[i]);
    if(c >= 32 && c < 127) o += static_cast<char>(c);
    else { o += "\\x"; o += hex[c >> 4]; o += hex[c & 15]; }
  }
  if(token.size() > 24) o += "...";
  return o + "'";
}

inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

/// Text read line by line: "\n", "\r\n" and a lone "\r" end a line; a UTF-8 byte order mark at the
/// start is skipped; `comment` (0 for none) starts a comment that runs to the end of the line.
/// A NUL byte or another control character is an error (a binary file read as text).
class Line_scanner {
public:
  Line_scanner(const std::string& path, std::string_view text, std::size_t first_line = 1, char comment = '#')
    : m_path(path), m_text(text), m_line(first_line - 1), m_comment(comment) {
    if(m_text.size() >= 3 && m_text.substr(0, 3) == "\xEF\xBB\xBF") m_pos = 3;
  }

  /// The tokens of the next line that has any (blank and comment-only lines are skipped); false
  /// at the end of the text.
  bool next(std::vector<std::string_view>& tokens) {
    while(m_pos < m_text.size()) {
      std::size_t end = m_pos;
      while(end < m_text.size() && m_text[end] != '\n' && m_text[end] != '\r') ++end;
      std::string_view line = m_text.substr(m_pos, end - m_pos);
      ++m_line;
      m_pos = end;
      if(m_pos < m_text.size()) m_pos += m_text[m_pos] == '\r' && m_pos + 1 < m_text.size() && m_text[m_pos + 1] == '\n' ? 2 : 1;
      if(m_comment) {
        const std::size_t c = line.find(m_comment);
        if(c != std::string_view::npos) line = line.substr(0, c);
      }
      tokenize(line, tokens);
      if(!tokens.empty()) return true;
    }
    tokens.clear();
    return false;
  }
  /// Line number (1-based) of the line `next` returned last.
  std::size_t line() const { return m_line; }
  /// Bytes not yet read.
  std::size_t remaining() const { return m_text.size() - m_pos; }
  /// Offset of the first byte not yet read.
  std::size_t offset() const { return m_pos; }
  [[noreturn]] void fail(const std::string& what) const { malformed(m_path, line_place(m_line), what); }

private:
  void tokenize(std::string_view line, std::vector<std::string_view>& tokens) const {
    tokens.clear();
    std::size_t i = 0;
    while(i < line.size()) {
      while(i < line.size() && is_blank(line[i])) ++i;
      if(i >= line.size()) break;
      std::size_t j = i;
      while(j < line.size() && !is_blank(line[j])) {
        const unsigned char c = static_cast<unsigned char>(line[j]);
        if(c < 32 || c == 127)
          malformed(m_path, line_place(m_line), "control byte " + quoted(line.substr(j, 1)) + " in a text file (binary data, or a corrupt file?)");
        ++j;
      }
      tokens.push_back(line.substr(i, j - i));
      i = j;
    }
  }
  const std::string& m_path;
  std::string_view m_text;
  std::size_t m_pos = 0;
  std::size_t m_line;
  char m_comment;
};

/// A real number: decimal or scientific notation, an optional sign, "nan" and "inf" accepted
/// (validation reports them), magnitudes past the double range become +-inf. False when the
/// token is not a number.
inline bool parse_real(std::string_view t, double& value) {
  if(t.empty()) return false;
  std::string_view body = t;
  bool negative = false;
  if(body[0] == '+' || body[0] == '-') {
    negative = body[0] == '-';
    body.remove_prefix(1);
    if(body.empty() || body[0] == '+' || body[0] == '-') return false;
  }
  double v = 0;
  const auto r = std::from_chars(body.data(), body.data() + body.size(), v, std::chars_format::general);
  if(r.ptr != body.data() + body.size()) return false;
  if(r.ec == std::errc::result_out_of_range) { // overflow to +-inf, underflow to 0 (as strtod does)
    const std::string copy(body);
    errno = 0;
    v = std::strtod(copy.c_str(), nullptr);
  } else if(r.ec != std::errc()) {
    return false;
  }
  value = negative ? -v : v;
  return true;
}

/// A non-negative integer index or count in [0, max]: digits only (no sign, point or exponent).
/// Returns an empty string on success, else why not.
inline std::string parse_unsigned(std::string_view t, std::uint64_t max, std::uint64_t& value) {
  if(t.empty()) return "an empty number";
  if(t[0] == '-') return "a negative number " + quoted(t);
  if(t[0] == '+') t.remove_prefix(1);
  std::uint64_t v = 0;
  const auto r = std::from_chars(t.data(), t.data() + t.size(), v, 10);
  if(r.ec == std::errc::result_out_of_range || (r.ec == std::errc() && r.ptr == t.data() + t.size() && v > max))
    return "a number too large " + quoted(t) + " (at most " + std::to_string(max) + ")";
  if(r.ec != std::errc() || r.ptr != t.data() + t.size()) {
    double d;
    if(parse_real(t, d)) return "not an integer: " + quoted(t);
    return "not a number: " + quoted(t);
  }
  value = v;
  return "";
}

/// The largest element count a text or binary section of `bytes` bytes can hold when each element
/// takes at least `min_bytes`.
inline std::uint64_t capacity(std::uint64_t bytes, std::uint64_t min_bytes) { return min_bytes ? bytes / min_bytes : bytes; }

} // namespace internal
} // namespace shapecorr

#endif
