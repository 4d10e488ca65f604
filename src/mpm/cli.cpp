// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "cli.h"
#include "standard_streams.h"

#include <CGAL/MPM/Input_error.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include <unistd.h>

namespace mpm {

namespace fs = std::filesystem;

// ---- Args ------------------------------------------------------------------

bool Args::has(const std::string& option) const
{
  return std::any_of(items.begin(), items.end(), [&](const Arg_item& i) { return i.option == option; });
}

std::string Args::text(const std::string& option, const std::string& fallback) const
{
  for(auto it = items.rbegin(); it != items.rend(); ++it)
    if(it->option == option) return it->value;
  return fallback;
}

long long Args::integer(const std::string& option, long long fallback) const
{
  return has(option) ? std::stoll(text(option)) : fallback; // checked while parsing
}

double Args::real(const std::string& option, double fallback) const
{
  return has(option) ? std::strtod(text(option).c_str(), nullptr) : fallback; // checked while parsing
}

std::vector<std::string> Args::positionals() const
{
  std::vector<std::string> r;
  for(const Arg_item& i : items)
    if(i.option.empty()) r.push_back(i.value);
  return r;
}

// ---- parsing ---------------------------------------------------------------

const std::vector<Option_spec>& common_options()
{
  static const std::vector<Option_spec> options = {
    {"json", 0, Value_kind::flag, "", "off", "print the summary as one JSON object on stdout"},
    {"progress", 0, Value_kind::flag, "", "on when stderr is a terminal",
     "show progress on stderr even when it is not a terminal"},
    {"binary", 0, Value_kind::flag, "", "off", "write PLY and STL meshes in binary (OFF and OBJ stay text)"},
    {"help", 'h', Value_kind::flag, "", "", "print this help and exit"},
  };
  return options;
}

namespace {

std::string describe_range(const Option_spec& o)
{
  std::ostringstream s;
  // Bounds at the type's limit (INT_MAX, UINT_MAX) are not worth printing.
  const bool has_min = std::isfinite(o.min), has_max = std::isfinite(o.max) && o.max < 2147483647.;
  if(has_min && has_max) s << "in " << (o.min_exclusive ? "(" : "[") << format_number(o.min, 10) << ", "
                           << format_number(o.max, 10) << "]";
  else if(has_min) s << (o.min_exclusive ? "> " : ">= ") << format_number(o.min, 10);
  else if(has_max) s << "<= " << format_number(o.max, 10);
  return s.str();
}

// Checks `value` against the option's type and range; throws Usage_error.
void check_value(const Option_spec& o, const std::string& value)
{
  const std::string what = "option --" + o.name + ": ";
  double number = 0;
  if(o.kind == Value_kind::integer)
  {
    const char* begin = value.c_str();
    char* end = nullptr;
    errno = 0;
    const long long v = std::strtoll(begin, &end, 10);
    if(value.empty() || *end != '\0' || std::isspace(static_cast<unsigned char>(value[0])))
      throw Usage_error(what + "'" + value + "' is not an integer");
    if(errno == ERANGE) throw Usage_error(what + "'" + value + "' is out of range");
    number = static_cast<double>(v);
  }
  else if(o.kind == Value_kind::real)
  {
    const char* begin = value.c_str();
    char* end = nullptr;
    errno = 0;
    number = std::strtod(begin, &end);
    if(value.empty() || *end != '\0' || std::isspace(static_cast<unsigned char>(value[0])))
      throw Usage_error(what + "'" + value + "' is not a number");
    if(!std::isfinite(number) || errno == ERANGE) throw Usage_error(what + "'" + value + "' is out of range");
  }
  else
  {
    if(value.empty()) throw Usage_error(what + "empty value");
    return;
  }
  if(number < o.min || (o.min_exclusive && number == o.min) || number > o.max)
    throw Usage_error(what + "'" + value + "' must be " + describe_range(o));
}

const Option_spec* find_option(const Command& c, const std::string& name, char short_name)
{
  for(const auto* list : {&c.options, &common_options()})
    for(const Option_spec& o : *list)
      if((!name.empty() && o.name == name) || (short_name != 0 && o.short_name == short_name)) return &o;
  return nullptr;
}

bool is_output(Value_kind kind) { return kind == Value_kind::output_file || kind == Value_kind::output_prefix; }

bool looks_like_option(const std::string& s)
{
  return s.size() > 1 && s[0] == '-' && !std::isdigit(static_cast<unsigned char>(s[1])) && s[1] != '.';
}

} // namespace

Value_kind option_kind(const Command& command, const std::string& option)
{
  if(option.empty()) return command.positionals_are_files ? Value_kind::input_file : Value_kind::text;
  const Option_spec* spec = find_option(command, option, 0);
  return spec != nullptr ? spec->kind : Value_kind::text;
}

bool wants_help(const std::vector<std::string>& arguments)
{
  for(const std::string& a : arguments)
  {
    if(a == "--") return false;
    if(a == "--help" || a == "-h") return true;
  }
  return false;
}

Args parse_arguments(const Command& command, const std::vector<std::string>& arguments)
{
  Args args;
  bool options_done = false;
  for(std::size_t i = 0; i < arguments.size(); ++i)
  {
    const std::string& a = arguments[i];
    if(options_done || !looks_like_option(a))
    {
      args.items.push_back({"", a});
      continue;
    }
    if(a == "--")
    {
      options_done = true;
      continue;
    }
    // --name, --name=value, -s, -sVALUE
    std::string name, inline_value, spelled;
    bool has_inline = false;
    const Option_spec* spec = nullptr;
    if(a.compare(0, 2, "--") == 0)
    {
      const std::size_t eq = a.find('=');
      name = a.substr(2, eq == std::string::npos ? std::string::npos : eq - 2);
      if(eq != std::string::npos) { has_inline = true; inline_value = a.substr(eq + 1); }
      spelled = "--" + name;
      spec = find_option(command, name, 0);
    }
    else
    {
      spelled = a.substr(0, 2);
      if(a.size() > 2) { has_inline = true; inline_value = a.substr(2); }
      spec = find_option(command, "", a[1]);
    }
    if(spec == nullptr)
      throw Usage_error("unknown option '" + spelled + "' for 'mpm " + command.name + "' (see 'mpm help " +
                        command.name + "')");
    if(!spec->repeatable && args.has(spec->name))
      throw Usage_error("option --" + spec->name + " given more than once");
    std::string value;
    if(spec->kind == Value_kind::flag)
    {
      if(has_inline) throw Usage_error("option --" + spec->name + " takes no value");
    }
    else if(has_inline)
      value = inline_value;
    else
    {
      if(i + 1 >= arguments.size() || arguments[i + 1].compare(0, 2, "--") == 0)
        throw Usage_error("option --" + spec->name + ": missing value " + spec->value_name);
      value = arguments[++i];
    }
    if(spec->kind != Value_kind::flag) check_value(*spec, value);
    args.items.push_back({spec->name, value});
  }

  const int n = static_cast<int>(args.positionals().size());
  if(n < command.min_positionals)
    throw Usage_error("'mpm " + command.name + "' needs " + command.operand + " (usage: mpm " + command.name + " " + command.synopsis + ")");
  if(command.max_positionals >= 0 && n > command.max_positionals)
    throw Usage_error("unexpected argument '" + args.positionals()[command.max_positionals] + "' for 'mpm " +
                      command.name + "'");
  return args;
}

std::string usage_text(const Command& c)
{
  std::ostringstream s;
  s << "Usage: mpm " << c.name << " " << c.synopsis << "\n\n" << c.summary << "\n";
  if(!c.description.empty()) s << "\n" << c.description << "\n";
  auto section = [&](const char* title, const std::vector<Option_spec>& options) {
    if(options.empty()) return;
    s << "\n" << title << ":\n";
    std::vector<std::string> left;
    std::size_t width = 0;
    for(const Option_spec& o : options)
    {
      std::string l = o.short_name ? std::string("-") + o.short_name + ", --" + o.name : "    --" + o.name;
      if(o.kind != Value_kind::flag) l += " " + o.value_name;
      width = std::max(width, l.size());
      left.push_back(l);
    }
    for(std::size_t i = 0; i < options.size(); ++i)
    {
      const Option_spec& o = options[i];
      std::string text = o.help;
      std::string range = (o.kind == Value_kind::integer || o.kind == Value_kind::real) ? describe_range(o) : "";
      std::replace(range.begin(), range.end(), ' ', '\x01'); // never break a range across lines
      if(!range.empty()) text += "; " + range;
      if(!o.default_text.empty()) text += " (default: " + o.default_text + ")";
      if(o.repeatable) text += " [repeatable]";
      // Wrap the description at 79 columns, aligned after the option column.
      const std::size_t column = width + 4, room = std::max<std::size_t>(30, 79 - column);
      std::istringstream words(text);
      std::string line, word;
      s << "  " << left[i] << std::string(width - left[i].size() + 2, ' ');
      bool first = true;
      while(words >> word)
      {
        if(!line.empty() && line.size() + 1 + word.size() > room)
        {
          s << (first ? "" : std::string(column, ' ')) << line << "\n";
          first = false;
          line.clear();
        }
        std::replace(word.begin(), word.end(), '\x01', ' ');
        line += (line.empty() ? "" : " ") + word;
      }
      s << (first ? "" : std::string(column, ' ')) << line << "\n";
    }
  };
  section("Options", c.options);
  section("Common options", common_options());
  s << "\nExit status: 0 success, 1 input or computation error, 2 usage error,\n"
       "3 result written with a warning.\n";
  return s.str();
}

// ---- Progress --------------------------------------------------------------

Progress::Progress(const std::string& command, bool requested)
  : command_(command)
{
  tty_ = ::isatty(STDERR_FILENO) != 0;
  enabled_ = requested || tty_;
}

Progress::~Progress() { done(); }

void Progress::update(const std::string& spelled_stage, double fraction)
{
  if(!enabled_) return;
  const std::string stage = as_the_user_wrote(spelled_stage);
  const int percent = static_cast<int>(std::floor(std::clamp(fraction, 0., 1.) * 100. + 1e-9));
  const bool new_stage = stage != stage_;
  if(!new_stage && percent == percent_) return;
  if(tty_)
  {
    std::fprintf(stderr, "\r\033[Kmpm %s: %s %3d%%", command_.c_str(), stage.c_str(), percent);
    line_open_ = true;
  }
  else if(new_stage || percent / 10 != percent_ / 10 || (percent == 100 && percent_ != 100))
    std::fprintf(stderr, "mpm %s: %s %d%%\n", command_.c_str(), stage.c_str(), percent);
  std::fflush(stderr);
  stage_ = stage;
  percent_ = percent;
}

void Progress::done()
{
  // The last stage is finished: say so, rather than stopping at its last step.
  if(enabled_ && !stage_.empty() && percent_ < 100) update(stage_, 1.);
  if(line_open_)
  {
    std::fputs("\r\033[K", stderr);
    std::fflush(stderr);
    line_open_ = false;
  }
  stage_.clear();
  percent_ = -1;
}

std::function<void(int, double)> iteration_progress(Progress& progress, const std::string& stage, double from,
                                                    double to, int max_iterations)
{
  return [&progress, stage, from, to, max_iterations](int iteration, double) {
    progress.update(stage, from + (to - from) * std::min(1., double(iteration) / std::max(1, max_iterations)));
  };
}

void Progress::warning(const std::string& message)
{
  if(line_open_) std::fputs("\r\033[K", stderr);
  line_open_ = false;
  std::fprintf(stderr, "mpm: warning: %s\n", as_the_user_wrote(message).c_str());
  std::fflush(stderr);
  percent_ = -1; // redraw the progress line at the next update
}

// ---- output ----------------------------------------------------------------

void print_json(const Json& object)
{
  std::cout << object.dump(2) << std::endl;
}

std::string format_number(double value, int digits)
{
  if(std::isnan(value)) return "nan";
  if(std::isinf(value)) return value > 0 ? "inf" : "-inf";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*g", digits, value);
  return buffer;
}

Table::Table(std::vector<std::string> headers, std::vector<bool> numeric)
  : headers_(std::move(headers)), numeric_(std::move(numeric))
{
  numeric_.resize(headers_.size(), false);
}

void Table::add_row(std::vector<std::string> cells)
{
  cells.resize(headers_.size());
  rows_.push_back(std::move(cells));
}

void Table::print(std::ostream& out, const std::string& indent) const
{
  std::vector<std::size_t> width(headers_.size());
  for(std::size_t c = 0; c < headers_.size(); ++c)
  {
    width[c] = headers_[c].size();
    for(const auto& r : rows_) width[c] = std::max(width[c], r[c].size());
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string l = indent;
    for(std::size_t c = 0; c < cells.size(); ++c)
    {
      const std::string pad(width[c] - cells[c].size(), ' ');
      const bool last = c + 1 == cells.size();
      l += numeric_[c] ? pad + cells[c] : cells[c] + (last ? "" : pad);
      if(!last) l += "  ";
    }
    while(!l.empty() && l.back() == ' ') l.pop_back();
    out << l << "\n";
  };
  line(headers_);
  for(const auto& r : rows_) line(r);
}

// ---- files -----------------------------------------------------------------

void refuse_overwriting(const std::string& output, const std::vector<std::string>& inputs)
{
  for(const std::string& input : inputs)
  {
    std::error_code ec;
    if(std::filesystem::equivalent(output, input, ec))
      throw CGAL::MPM::Input_error(output, "", "would overwrite the input \"" + input +
                                                 "\" of this command; write to another file");
  }
}

void refuse_outputs_over_inputs(const Command& command, const Args& args)
{
  std::vector<std::string> inputs, outputs;
  for(const Arg_item& item : args.items)
  {
    std::error_code ec;
    if(is_output(option_kind(command, item.option)))
    {
      outputs.push_back(item.value);
      for(const std::string& extension : command.prefix_extensions) outputs.push_back(item.value + extension);
    }
    else if((item.option.empty() || !item.value.empty()) && std::filesystem::is_regular_file(item.value, ec))
      inputs.push_back(item.value);
  }
  for(const std::string& output : outputs) refuse_overwriting(output, inputs);
}

void check_memory(const std::string& option, const std::string& value, double bytes)
{
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
  if(pages <= 0 || page <= 0) return;
  const double machine = double(pages) * double(page);
  if(bytes <= machine) return;
  const auto gigabytes = [](double b) { return format_number(b / (1024. * 1024. * 1024.), 3) + " GB"; };
  throw Usage_error("option --" + option + ": " + value + " needs about " + gigabytes(bytes) +
                    " of memory; this machine has " + gigabytes(machine));
}

void check_output_prefix(const Command& command, const Args& args)
{
  if(command.prefix_extensions.empty() || !args.has("output")) return;
  const std::string prefix = args.text("output");
  for(const Option_spec& spec : command.options)
    if(spec.name == "output" && spec.value_name.find("DIR") != std::string::npos) return;
  std::error_code ec;
  if(prefix.empty() || prefix.back() == '/' || std::filesystem::is_directory(prefix, ec) ||
     std::filesystem::path(prefix).filename().string().front() == '.')
    throw Usage_error("option --output: '" + prefix + "' is a directory, not a prefix: give a file name without " +
                      "extension, such as '" + (std::filesystem::path(prefix) / "name").string() + "'");
}

void ensure_parent_directory(const std::string& path)
{
  const fs::path parent = fs::path(path).parent_path();
  if(parent.empty()) return;
  std::error_code ec;
  if(fs::is_directory(parent, ec)) return;
  fs::create_directories(parent, ec);
  if(ec) throw CGAL::MPM::Input_error(parent.string(), "", "cannot create directory (" + ec.message() + ")");
}

} // namespace mpm
