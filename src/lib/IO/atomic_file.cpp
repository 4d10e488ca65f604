// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Atomic_file.h>
#include <CGAL/MPM/Input_error.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <vector>

#include <unistd.h>
#include <fstream>
#include <iterator>
#include <random>
#include <sstream>
#include <system_error>

namespace CGAL {
namespace MPM {
namespace internal {

namespace fs = std::filesystem;

namespace {

// A name no other writer (thread or process) picks at the same time: the
// random part separates processes, the counter separates threads of one.
// The target's name is shortened so that the whole name fits the file
// system's limit (a valid 250-character output name must stay writable).
fs::path unique_temporary_path(const fs::path& target)
{
  static std::atomic<unsigned long> counter{0};
  static const unsigned long long process_salt = std::random_device{}();
  std::ostringstream suffix;
  suffix << ".tmp." << std::hex << process_salt << '.' << counter++;
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const long limit = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  const std::size_t room = std::size_t(limit > 0 ? limit : 255) - 1 - suffix.str().size();
  const std::string name = target.filename().string();
  return target.parent_path() / ("." + name.substr(0, std::min(name.size(), room)) + suffix.str());
}

// Temporary files being written, for the signal handler: fixed slots, so
// that the handler reads them without allocating or locking.
constexpr int temporary_slots = 32;
constexpr std::size_t temporary_path_size = 4096;
char temporary_paths[temporary_slots][temporary_path_size];
std::atomic<bool> temporary_used[temporary_slots];
std::mutex temporary_slot_mutex;

int register_temporary(const fs::path& path)
{
  const std::string text = path.string();
  if(text.size() >= temporary_path_size) return -1;
  std::lock_guard<std::mutex> lock(temporary_slot_mutex);
  for(int k = 0; k < temporary_slots; ++k)
    if(!temporary_used[k].load())
    {
      std::memcpy(temporary_paths[k], text.c_str(), text.size() + 1);
      temporary_used[k].store(true);
      return k;
    }
  return -1;
}

void unregister_temporary(int slot)
{
  if(slot >= 0) temporary_used[slot].store(false);
}

extern "C" void remove_temporaries_and_reraise(int signal_number)
{
  for(int k = 0; k < temporary_slots; ++k)
    if(temporary_used[k].load()) ::unlink(temporary_paths[k]);
  std::signal(signal_number, SIG_DFL);
  std::raise(signal_number);
}

// Removes the temporary file on every exit path except a successful rename.
struct Temporary_file_guard
{
  fs::path path;
  int slot = register_temporary(path);
  bool armed = true;
  ~Temporary_file_guard()
  {
    unregister_temporary(slot);
    if(armed) {
      std::error_code ignored;
      fs::remove(path, ignored);
    }
  }
};

// Files the command read, when the caller asked to protect them.
std::atomic<bool> guarding_inputs{false};
std::mutex input_mutex;
std::vector<fs::path> inputs;

void note_input(const std::string& path)
{
  if(!guarding_inputs.load()) return;
  std::lock_guard<std::mutex> lock(input_mutex);
  inputs.emplace_back(path);
}

void refuse_overwriting_an_input(const std::string& path, const fs::path& target)
{
  if(!guarding_inputs.load()) return;
  std::lock_guard<std::mutex> lock(input_mutex);
  for(const fs::path& input : inputs)
  {
    std::error_code ec;
    if(fs::equivalent(input, target, ec))
      throw Input_error(path, "", "is an input of this command (\"" + input.string() +
                                    "\"): it is not overwritten; write to another file");
  }
}

// The file a write to `path` lands in: symbolic links followed (a dangling
// link's target is created), so that the link stays a link.
fs::path resolved_target(const fs::path& path)
{
  fs::path target = path;
  std::error_code ec;
  for(int depth = 0; depth < 40 && fs::is_symlink(fs::symlink_status(target, ec)); ++depth)
  {
    const fs::path link = fs::read_symlink(target, ec);
    if(ec) break;
    target = link.is_absolute() ? link : target.parent_path() / link;
  }
  return target;
}

// Devices, FIFOs and sockets are written as they are: replacing one by a
// regular file would, as root, replace /dev/null.
void write_directly(const std::string& path, const fs::path& target, const std::function<void(std::ostream&)>& write,
                    bool binary)
{
  std::ofstream out(target, binary ? std::ios::out | std::ios::binary : std::ios::out);
  if(!out) throw Input_error(path, "", "cannot write: cannot open it for writing");
  write(out);
  out.flush();
  if(!out) throw Input_error(path, "", "cannot write: output error");
}

} // namespace

void write_file_atomically(const std::string& path, const std::function<void(std::ostream&)>& write,
                           bool binary)
{
  const fs::path target = resolved_target(path);
  std::error_code ec;
  if(fs::is_directory(target, ec))
    throw Input_error(path, "", "cannot write: the path is a directory");
  refuse_overwriting_an_input(path, target);
  const fs::file_status status = fs::status(target, ec);
  if(fs::exists(status) && !fs::is_regular_file(status)) return write_directly(path, target, write, binary);

  fs::path temporary;
  do { temporary = unique_temporary_path(target); } while(fs::exists(temporary, ec));

  Temporary_file_guard guard{temporary};
  {
    std::ofstream out(temporary, binary ? std::ios::out | std::ios::binary | std::ios::trunc
                                        : std::ios::out | std::ios::trunc);
    if(!out)
      throw Input_error(path, "", "cannot write: cannot create a file in directory \"" +
                                      (target.has_parent_path() ? target.parent_path().string()
                                                                : std::string(".")) + "\"");
    write(out);
    out.flush();
    if(!out)
      throw Input_error(path, "", "cannot write: output error (disk full?)");
    out.close();
    if(out.fail())
      throw Input_error(path, "", "cannot write: output error while closing the file");
  }

  // Keep the permissions a user gave the file being replaced.
  if(fs::exists(target, ec))
    fs::permissions(temporary, fs::status(target, ec).permissions(), ec);

  fs::rename(temporary, target, ec);
  if(ec)
    throw Input_error(path, "", "cannot write: " + ec.message());
  guard.armed = false;
}

void guard_inputs_against_overwriting(bool guard)
{
  std::lock_guard<std::mutex> lock(input_mutex);
  inputs.clear();
  guarding_inputs.store(guard);
}

void remove_temporary_files_on_signals()
{
  for(int signal_number : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) std::signal(signal_number, remove_temporaries_and_reraise);
}

int remove_on_signals(const std::string& path) { return register_temporary(path); }

void forget_on_signals(int slot) { unregister_temporary(slot); }

void check_readable_file(const std::string& path)
{
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if(!fs::exists(status))
    throw Input_error(path, "", "file not found");
  if(fs::is_directory(status))
    throw Input_error(path, "", "is a directory, not a file");
  if(!std::ifstream(path, std::ios::in | std::ios::binary))
    throw Input_error(path, "", "cannot open the file for reading (permission denied?)");
  note_input(path);
}

std::string read_file(const std::string& path)
{
  check_readable_file(path);
  std::ifstream in(path, std::ios::in | std::ios::binary);
  if(!in)
    throw Input_error(path, "", "cannot open the file for reading");
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if(in.bad())
    throw Input_error(path, "", "read error");
  return bytes;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
