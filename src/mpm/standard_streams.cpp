// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "standard_streams.h"

#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Atomic_file.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <sstream>

#include <unistd.h>

namespace mpm {

namespace {

namespace fs = std::filesystem;

// Temporary names and what the user wrote for them; kept after the command
// ends, because its error is reported after its files were removed.
std::vector<std::string>& temporary_names()
{
  static std::vector<std::string> names;
  return names;
}

// The extension the readers need to recognize a mesh on standard input
// (OFF, PLY, STL, OBJ), or "" for any other file (labels, JSON, a model).
std::string mesh_extension_of(const std::string& bytes)
{
  std::istringstream lines(bytes);
  std::string line, word;
  while(std::getline(lines, line))
  {
    std::istringstream words(line);
    if(!(words >> word) || word[0] == '#') continue;
    if(word.size() >= 3 && word.compare(word.size() - 3, 3, "OFF") == 0) return ".off";
    if(word == "ply") return ".ply";
    if(word == "solid") return ".stl";
    for(const char* obj : {"v", "vn", "vt", "vp", "f", "l", "o", "g", "s", "mtllib", "usemtl"})
      if(word == obj) return ".obj";
    break;
  }
  // Binary STL: an 80-byte header, a facet count, 50 bytes per facet.
  if(bytes.size() >= 84)
  {
    const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(bytes[i])); };
    const std::uint32_t facets = byte(80) | byte(81) << 8 | byte(82) << 16 | byte(83) << 24;
    if(84 + 50 * std::uintmax_t(facets) == bytes.size()) return ".stl";
  }
  return "";
}

// A new empty file `/tmp/mpm-ROLE-XXXXXX` + extension, registered as a name for `-`.
std::string make_temporary(const std::string& role, const std::string& extension)
{
  std::string pattern = (fs::temp_directory_path() / ("mpm-" + role + "-XXXXXX" + extension)).string();
  std::vector<char> name(pattern.begin(), pattern.end());
  name.push_back('\0');
  const int fd = ::mkstemps(name.data(), static_cast<int>(extension.size()));
  if(fd < 0)
    throw CGAL::MPM::Input_error(pattern, "", "cannot create a temporary file for standard " + role);
  ::close(fd);
  temporary_names().push_back(name.data());
  return name.data();
}

std::string read_standard_input()
{
  std::string bytes;
  char chunk[1 << 16];
  for(std::size_t n; (n = std::fread(chunk, 1, sizeof chunk, stdin)) > 0;) bytes.append(chunk, n);
  if(std::ferror(stdin)) throw CGAL::MPM::Input_error("-", "", "cannot read standard input");
  return bytes;
}

// Passes text on to `target` a line at a time, with temporary names spelled
// as the user wrote them.
class Spelling_buffer : public std::streambuf
{
public:
  explicit Spelling_buffer(std::streambuf* target) : target_(target) {}
  ~Spelling_buffer() override { sync(); }

protected:
  int overflow(int c) override
  {
    if(c == traits_type::eof()) return sync() == 0 ? 0 : traits_type::eof();
    line_.push_back(static_cast<char>(c));
    if(c == '\n' && sync() != 0) return traits_type::eof();
    return c;
  }
  int sync() override
  {
    if(line_.empty()) return target_->pubsync();
    const std::string text = as_the_user_wrote(line_);
    line_.clear();
    if(target_->sputn(text.data(), std::streamsize(text.size())) != std::streamsize(text.size())) return -1;
    return target_->pubsync();
  }

private:
  std::streambuf* target_;
  std::string line_;
};

} // namespace

std::string as_the_user_wrote(std::string text)
{
  for(const std::string& name : temporary_names())
    for(std::size_t at; (at = text.find(name)) != std::string::npos;) text.replace(at, name.size(), "-");
  return text;
}

Standard_streams::Standard_streams(const Command& command, Args& args, bool json)
{
  for(Arg_item& item : args.items)
  {
    if(item.value != "-") continue;
    const Value_kind kind = option_kind(command, item.option);
    const std::string what = item.option.empty() ? command.operand + " '-'" : "option --" + item.option + ": '-'";
    if(kind == Value_kind::output_prefix)
      throw Usage_error(what + " (standard output) cannot stand for the several files 'mpm " + command.name +
                        "' writes; give a " + (command.prefix_extensions.empty() ? "directory" : "prefix"));
    if(kind == Value_kind::output_file)
    {
      if(!output_.path.empty()) throw Usage_error(what + ": only one output can go to standard output");
      if(json) throw Usage_error(what + " and --json both write to standard output; give one of them a file");
      output_.path = make_temporary("output", ".off");
      output_.slot = CGAL::MPM::internal::remove_on_signals(output_.path);
      item.value = output_.path;
    }
    else if(kind == Value_kind::input_file)
    {
      if(!input_.path.empty()) throw Usage_error(what + ": only one input can be read from standard input");
      if(::isatty(STDIN_FILENO))
        throw Usage_error(what + " reads standard input, which is a terminal: pipe or redirect a file into mpm");
      const std::string bytes = read_standard_input();
      input_.path = make_temporary("input", mesh_extension_of(bytes));
      input_.slot = CGAL::MPM::internal::remove_on_signals(input_.path);
      std::ofstream copy(input_.path, std::ios::binary);
      copy.write(bytes.data(), std::streamsize(bytes.size()));
      if(!copy.flush()) throw CGAL::MPM::Input_error("-", "", "cannot copy standard input to " + input_.path);
      item.value = input_.path;
    }
  }
  if(input_.path.empty() && output_.path.empty()) return;
  // With `-o -` standard output carries the file: the summary goes to stderr.
  cout_buffer_ = std::cout.rdbuf();
  spelling_ = std::make_unique<Spelling_buffer>(output_.path.empty() ? cout_buffer_ : std::cerr.rdbuf());
  std::cout.rdbuf(spelling_.get());
}

Standard_streams::Temporary::~Temporary()
{
  if(path.empty()) return;
  CGAL::MPM::internal::forget_on_signals(slot);
  std::error_code ignored;
  fs::remove(path, ignored);
}

Standard_streams::~Standard_streams()
{
  if(cout_buffer_ == nullptr) return;
  std::cout.flush();
  std::cout.rdbuf(cout_buffer_);
}

void Standard_streams::send_output()
{
  if(output_.path.empty()) return;
  std::cout.flush();
  std::ifstream in(output_.path, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0)
    throw CGAL::MPM::Input_error("-", "", "cannot write to standard output");
}

} // namespace mpm
