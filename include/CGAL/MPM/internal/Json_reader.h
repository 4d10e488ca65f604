// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INTERNAL_JSON_READER_H
#define CGAL_MPM_INTERNAL_JSON_READER_H

#include <nlohmann/json.hpp>

#include <initializer_list>
#include <string>
#include <utility>

namespace CGAL {
namespace MPM {
namespace internal {

// Typed access to the JSON file formats of the package. Every failure throws
// Input_error naming the source and the element (`handles[3].target`), so
// the format readers only state what they expect.
class Json_reader
{
public:
  using json = nlohmann::json;

  explicit Json_reader(std::string source) : source_(std::move(source)) {}

  const std::string& source() const { return source_; }

  // The text as a JSON object whose optional "format" and "version" keys, when
  // present, must be `format` and `version`. Malformed JSON and numbers beyond
  // the double range (`1e999`) throw Input_error too. `name` is what messages
  // call the document ("annotation": "the annotation must be a JSON object",
  // "annotation version 2, ..."); by default "a <format> file" and "<format>".
  json parse_document(const std::string& text, const char* format, int version,
                      const char* name = nullptr) const;

  // Rejects keys outside `allowed`; misspelt optional keys would otherwise be
  // silently ignored.
  void check_keys(const json& object, const std::string& element,
                  std::initializer_list<const char*> allowed) const;

  const json& object_of(const json& j, const std::string& element) const;
  const json& array_of(const json& j, const std::string& element) const;
  std::string string_of(const json& j, const std::string& element) const;
  double number_of(const json& j, const std::string& element) const;
  int integer_of(const json& j, const std::string& element) const;
  int non_negative(const json& j, const std::string& element) const;

  [[noreturn]] void fail(const std::string& element, const std::string& problem) const;

private:
  std::string source_;
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#endif
