// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#ifndef CGAL_MPM_NAMED_PARAMETERS_H
#define CGAL_MPM_NAMED_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>

namespace CGAL {
namespace MPM {
namespace internal_np {

enum face_part_type_t { face_part_type };
enum vertex_is_seam_t { vertex_is_seam };

} // namespace internal_np

/// \ingroup PkgMPMRef
/// CGAL's named parameters with the package's own on top: a chain started
/// by `CGAL::MPM::parameters::face_part_type_map()` or
/// `vertex_is_seam_map()` takes both of them and every CGAL named parameter
/// (`vertex_point_map`, ...). CGAL's own chains cannot take the package's,
/// so a chain that mixes them starts with one of the package's.
template <class T, class Tag, class Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base>
{
  /// The chain so far.
  using self = Named_function_parameters<T, Tag, Base>;

  /// The parameter `v` on top of `b`.
  Named_function_parameters(const T& v, const Base& b) : CGAL::Named_function_parameters<T, Tag, Base>(v, b) {}
  /// The parameter `v` alone.
  explicit Named_function_parameters(const T& v) : CGAL::Named_function_parameters<T, Tag, Base>(v) {}

  /// Adds `face_part_type_map`: a `WritablePropertyMap` from faces to `int`
  /// that receives each face's part type.
  template <class Map>
  Named_function_parameters<Map, internal_np::face_part_type_t, self> face_part_type_map(const Map& m) const
  {
    return {m, *this};
  }

  /// Adds `vertex_is_seam_map`: a `WritablePropertyMap` from vertices to a
  /// type constructible from `bool` that receives whether a vertex lies on
  /// a seam between parts.
  template <class Map>
  Named_function_parameters<Map, internal_np::vertex_is_seam_t, self> vertex_is_seam_map(const Map& m) const
  {
    return {m, *this};
  }
};

namespace parameters {

// So that `parameters::` inside the package still finds CGAL's.
using namespace CGAL::parameters;

/// \ingroup PkgMPMRef
/// Named parameter: a `WritablePropertyMap` from the face descriptor to
/// `int` that receives the part type of each face (`copy_training_example()`,
/// `assemble()` over a face graph).
template <class Map>
Named_function_parameters<Map, internal_np::face_part_type_t> face_part_type_map(const Map& m)
{
  return Named_function_parameters<Map, internal_np::face_part_type_t>(m);
}

/// \ingroup PkgMPMRef
/// Named parameter: a `WritablePropertyMap` from the vertex descriptor to
/// a type constructible from `bool` that receives `true` for the vertices
/// of faces of more than one part (the seams), `false` for the others.
/// (CGAL 5.5 cannot read `bool` properties of an OpenMesh mesh: take `int`
/// there.)
template <class Map>
Named_function_parameters<Map, internal_np::vertex_is_seam_t> vertex_is_seam_map(const Map& m)
{
  return Named_function_parameters<Map, internal_np::vertex_is_seam_t>(m);
}

} // namespace parameters
} // namespace MPM
} // namespace CGAL

#endif
