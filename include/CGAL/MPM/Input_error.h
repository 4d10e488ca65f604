// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_INPUT_ERROR_H
#define CGAL_MPM_INPUT_ERROR_H

#include <stdexcept>
#include <string>

namespace CGAL {
namespace MPM {

/// \ingroup PkgMPMRef
/// Thrown for every problem with user input: a file that cannot be read, a
/// mesh, label, annotation or model that is malformed. `what()` is one line
/// naming the file (when there is one), the element and what is wrong, e.g.
/// `hand.off: face 17: degenerate triangle (zero area)`.
class Input_error : public std::runtime_error
{
public:
  /// `source` is a file name or a short description of the in-memory input
  /// (may be empty), `element` names the offending element (may be empty).
  Input_error(const std::string& source, const std::string& element, const std::string& problem)
    : std::runtime_error(compose(source, element, problem)),
      source_(source), element_(element), problem_(problem)
  {}

  /// The file or input the error is about.
  const std::string& source() const { return source_; }
  /// The element at fault (`face 17`, `label 3`, `part type "tip"`), or empty.
  const std::string& element() const { return element_; }
  /// What is wrong, without file and element.
  const std::string& problem() const { return problem_; }

private:
  static std::string compose(const std::string& s, const std::string& e, const std::string& p)
  {
    std::string r;
    if(!s.empty()) r += s + ": ";
    if(!e.empty()) r += e + ": ";
    return r + p;
  }
  std::string source_, element_, problem_;
};

/// \ingroup PkgMPMRef
/// Thrown when a computation cannot produce a meaningful result (for example a
/// shape space of instances that do not correspond). The message names the
/// part type or docking at fault.
class Computation_error : public std::runtime_error
{
public:
  /// Builds the error from a one-line message.
  explicit Computation_error(const std::string& what) : std::runtime_error(what) {}
};

} // namespace MPM
} // namespace CGAL

#endif
