// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/internal/Json_reader.h>
#include <CGAL/MPM/Input_error.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <limits>
#include <set>
#include <vector>

namespace CGAL {
namespace MPM {
namespace internal {

namespace {

// nlohmann's messages start with an exception id users need not see and
// quote the text near the error, which may hold line breaks.
std::string one_line(std::string s)
{
  const std::size_t id_end = s.find("] ");
  if(s.rfind("[json.exception", 0) == 0 && id_end != std::string::npos) s.erase(0, id_end + 2);
  for(char& c : s)
    if(std::iscntrl(static_cast<unsigned char>(c))) c = ' ';
  return s;
}

} // namespace

Json_reader::json Json_reader::parse_document(const std::string& text, const char* format, int version,
                                              const char* name) const
{
  // nlohmann keeps the last of two equal keys silently: a duplicate is
  // refused, named by its path (`parts[1].label`).
  struct Open_container
  {
    bool array = false;
    int index = -1;          // arrays: the element being read
    std::string key;         // objects: the key being read
    std::set<std::string> keys;
  };
  std::vector<Open_container> open;
  std::string duplicate;
  const auto path_to = [&open](const std::string& key) {
    std::string path;
    for(const Open_container& c : open)
      if(&c != &open.back()) path += c.array ? "[" + std::to_string(c.index) + "]" : (path.empty() ? "" : ".") + c.key;
    return path + (path.empty() ? "" : ".") + key;
  };
  const json::parser_callback_t check_duplicates = [&](int, json::parse_event_t event, json& parsed) {
    using Event = json::parse_event_t;
    const bool element_starts = event == Event::object_start || event == Event::array_start || event == Event::value;
    if(element_starts && !open.empty() && open.back().array) ++open.back().index;
    if(event == Event::object_start || event == Event::array_start)
      open.push_back({event == Event::array_start, -1, "", {}});
    else if((event == Event::object_end || event == Event::array_end) && !open.empty())
      open.pop_back();
    else if(event == Event::key && !open.empty())
    {
      open.back().key = parsed.get<std::string>();
      if(!open.back().keys.insert(open.back().key).second && duplicate.empty()) duplicate = path_to(open.back().key);
    }
    return true;
  };
  json root;
  try {
    root = json::parse(text, check_duplicates);
  } catch(const json::parse_error& e) {
    fail("", "malformed JSON at byte " + std::to_string(e.byte) + ": " + one_line(e.what()));
  } catch(const json::exception& e) { // numbers beyond the double range
    fail("", "malformed JSON: " + one_line(e.what()));
  }
  if(!duplicate.empty()) fail(duplicate, "the key is given twice (a JSON object names each key once)");
  if(!root.is_object())
    fail("", (name ? std::string("the ") + name : std::string("a ") + format + " file") +
               " must be a JSON object, not " + root.type_name());
  if(root.contains("format") && string_of(root["format"], "format") != format)
    fail("format", "\"" + root["format"].get<std::string>() + "\" is not \"" + format + "\"");
  if(root.contains("version")) {
    const int found = integer_of(root["version"], "version");
    if(found != version)
      fail("version", std::string(name ? name : format) + " version " + std::to_string(found) +
                        ", this build reads version " +
                        std::to_string(version));
  }
  return root;
}

void Json_reader::check_keys(const json& object, const std::string& element,
                             std::initializer_list<const char*> allowed) const
{
  for(auto it = object.begin(); it != object.end(); ++it)
    if(std::none_of(allowed.begin(), allowed.end(), [&](const char* k) { return it.key() == k; })) {
      std::string list;
      for(const char* k : allowed) list += (list.empty() ? "" : ", ") + std::string(k);
      fail(element.empty() ? "key \"" + it.key() + "\"" : element,
           "unknown key \"" + it.key() + "\" (allowed: " + list + ")");
    }
}

const Json_reader::json& Json_reader::object_of(const json& j, const std::string& element) const
{
  if(!j.is_object()) fail(element, "must be an object, not " + std::string(j.type_name()));
  return j;
}

const Json_reader::json& Json_reader::array_of(const json& j, const std::string& element) const
{
  if(!j.is_array()) fail(element, "must be an array, not " + std::string(j.type_name()));
  return j;
}

std::string Json_reader::string_of(const json& j, const std::string& element) const
{
  if(!j.is_string()) fail(element, "must be a string, not " + std::string(j.type_name()));
  return j.get<std::string>();
}

double Json_reader::number_of(const json& j, const std::string& element) const
{
  if(!j.is_number()) fail(element, "must be a number, not " + std::string(j.type_name()));
  return j.get<double>();
}

int Json_reader::integer_of(const json& j, const std::string& element) const
{
  if(!j.is_number_integer())
    fail(element, "must be an integer, not " + (j.is_number() ? j.dump() : std::string(j.type_name())));
  const auto value = j.get<std::int64_t>();
  if(j.is_number_unsigned() ? j.get<std::uint64_t>() > std::uint64_t(std::numeric_limits<int>::max())
                            : (value > std::numeric_limits<int>::max() || value < std::numeric_limits<int>::min()))
    fail(element, j.dump() + " is too large");
  return int(value);
}

int Json_reader::non_negative(const json& j, const std::string& element) const
{
  const int value = integer_of(j, element);
  if(value < 0) fail(element, "must not be negative (got " + std::to_string(value) + ")");
  return value;
}

void Json_reader::fail(const std::string& element, const std::string& problem) const
{
  throw Input_error(source_, element, problem);
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
