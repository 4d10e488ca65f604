// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_MESH_FILE_CHECKS_H
#define CGAL_MPM_INTERNAL_MESH_FILE_CHECKS_H

// What reading a mesh file checks before and after CGAL reads it, so that a
// bad file gets a message naming the element: the text scanning shared by
// the OFF, OBJ and .seg readers, the OFF and OBJ checks
// (mesh_file_text_checks.cpp) and the PLY checks and face properties
// (mesh_file_ply_checks.cpp).

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

// The extension of `path`, lower case, with its dot (".off").
inline std::string lower_extension(const std::string& path)
{
  std::string e = std::filesystem::path(path).extension().string();
  std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return e;
}

// A token from a file, fit for a one-line message: garbage bytes would
// otherwise break the line or the terminal.
inline std::string printable(std::string_view token)
{
  std::string r = "\"";
  for(std::size_t i = 0; i < token.size() && i < 24; ++i)
    r += std::isprint(static_cast<unsigned char>(token[i])) ? token[i] : '?';
  if(token.size() > 24) r += "...";
  return r + "\"";
}

// How messages name an element.
inline std::string face_name(int f) { return "face " + std::to_string(f); }
inline std::string vertex_name(int v) { return "vertex " + std::to_string(v); }

// Largest coordinate magnitude accepted: its square, and sums of a few such
// squares, stay far below the largest double (1.8e308).
inline constexpr double max_coordinate_magnitude = 1e150;


// ----------------------------------------------------------------------------
// Text scanning, shared by the OFF header check, the diagnosis of files CGAL
// rejects and the .seg reader.

struct Token
{
  std::string_view text;
  int line = 0;
};

class Text_scanner
{
public:
  explicit Text_scanner(std::string_view text) : text_(text) {}

  // Next white-space separated token; '#' starts a comment up to the end of the line.
  bool next(Token& t)
  {
    for(;;) {
      while(pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
        if(text_[pos_] == '\n') ++line_;
        ++pos_;
      }
      if(pos_ >= text_.size()) return false;
      if(comments_ && text_[pos_] == '#') {
        while(pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        continue;
      }
      break;
    }
    const std::size_t b = pos_;
    while(pos_ < text_.size() && !std::isspace(static_cast<unsigned char>(text_[pos_]))
          && !(comments_ && text_[pos_] == '#'))
      ++pos_;
    t.text = text_.substr(b, pos_ - b);
    t.line = line_;
    return true;
  }

  // The tokens left on the line of the last token (OFF vertices and faces are lines).
  std::vector<Token> rest_of_line()
  {
    std::vector<Token> r;
    const int line = line_;
    Token t;
    std::size_t save_pos = pos_;
    int save_line = line_;
    while(next(t) && t.line == line) {
      r.push_back(t);
      save_pos = pos_;
      save_line = line_;
    }
    pos_ = save_pos;
    line_ = save_line;
    return r;
  }

  std::size_t position() const { return pos_; }
  // Skips the character at the current position (even a '#').
  void skip_character() { if(pos_ < text_.size()) ++pos_; }
  void disable_comments() { comments_ = false; }

private:
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
  bool comments_ = true;
};

template <class Integer>
bool parse_integer(std::string_view s, Integer& value)
{
  if(!s.empty() && s.front() == '+') s.remove_prefix(1);
  const auto r = std::from_chars(s.data(), s.data() + s.size(), value);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// `s` as a number (strtod: also "nan" and "inf", to be reported as such).
bool parse_double(std::string_view s, double& value);
// A vertex coordinate of a text mesh file (OFF, OBJ) must be a finite number.
void check_coordinate(const std::string& path, const std::string& element, int line, std::string_view text);
// A text file that ends before all the elements its header announced.
[[noreturn]] void throw_truncated(const std::string& path, std::uint64_t read, std::uint64_t announced,
                                  const char* elements);

// OFF and OBJ (mesh_file_text_checks.cpp): a header announcing more than
// the file can hold; the lines CGAL would misread (returns a warning for
// text after the last face); why CGAL rejected a file.
void check_off_counts_fit(const std::string& path, std::uintmax_t file_size);
std::string check_off_lines(const std::string& path);
void diagnose_off(const std::string& path, const std::string& text);
void diagnose_obj(const std::string& path, const std::string& text);

// PLY (mesh_file_ply_checks.cpp): the header and the body's size and types;
// a per-face integer property (labels) by name.
void check_ply_header(const std::string& path, std::uintmax_t file_size);
std::vector<int> read_ply_face_property(const std::string& path, const std::string& name);

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
