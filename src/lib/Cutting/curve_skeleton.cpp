// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Kept in its own translation unit: CGAL's skeletonization is a heavy
// template that only joint cutting needs, and it is made deterministic here.
#include <CGAL/MPM/internal/Curve_skeleton.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/internal/Indexed_surface_mesh.h>

// What the skeletonization uses besides its own mesh keeps the default
// allocator: included before CGAL_ALLOCATOR is redefined below.
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Eigen_solver_traits.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/compute_normal.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/copy_face_graph.h>

#include <sys/mman.h>

#include <cstddef>
#include <exception>
#include <new>
#include <type_traits>

namespace CGAL {
namespace MPM {
namespace internal {

// CGAL's mean curvature flow skeletonization works on its own Polyhedron_3
// copy of the mesh and keeps the edges to collapse in a std::set ordered by
// halfedge handles, that is by address: the skeleton depended on where the
// allocator put those halfedges, which changed with everything the process
// had allocated and freed before (a test got other cuts than the same call in
// `mpm`). Its polyhedron is allocated from one contiguous range handed out in
// increasing addresses and never reused, so the addresses are in allocation
// order and the skeleton the same on every run.
class Skeleton_arena
{
public:
  Skeleton_arena()
  {
    void* p = mmap(nullptr, capacity, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
    if(p != MAP_FAILED) base_ = static_cast<char*>(p);
    previous_ = current;
    current = this;
  }
  ~Skeleton_arena()
  {
    current = previous_;
    if(base_) munmap(base_, capacity);
  }
  Skeleton_arena(const Skeleton_arena&) = delete;
  Skeleton_arena& operator=(const Skeleton_arena&) = delete;

  // Null when the range is full or absent: the caller falls back to the heap.
  void* allocate(std::size_t bytes)
  {
    const std::size_t start = (used_ + alignof(std::max_align_t) - 1) / alignof(std::max_align_t) * alignof(std::max_align_t);
    if(!base_ || start + bytes > capacity) return nullptr;
    used_ = start + bytes;
    return base_ + start;
  }
  bool owns(const void* p) const
  {
    return base_ && static_cast<const char*>(p) >= base_ && static_cast<const char*>(p) < base_ + capacity;
  }

  static thread_local Skeleton_arena* current;

private:
  static constexpr std::size_t capacity = std::size_t(1) << 33; // 8 GiB reserved, committed as used
  char* base_ = nullptr;
  std::size_t used_ = 0;
  Skeleton_arena* previous_ = nullptr;
};

thread_local Skeleton_arena* Skeleton_arena::current = nullptr;

template <class T>
struct Skeleton_allocator
{
  using value_type = T;
  template <class U>
  struct rebind
  {
    using other = Skeleton_allocator<U>;
  };
  Skeleton_allocator() noexcept = default;
  template <class U>
  Skeleton_allocator(const Skeleton_allocator<U>&) noexcept
  {
  }
  T* allocate(std::size_t n)
  {
    if(Skeleton_arena* arena = Skeleton_arena::current)
      if(void* p = arena->allocate(n * sizeof(T))) return static_cast<T*>(p);
    return static_cast<T*>(::operator new(n * sizeof(T)));
  }
  void deallocate(T* p, std::size_t) noexcept
  {
    const Skeleton_arena* arena = Skeleton_arena::current;
    if(!(arena && arena->owns(p))) ::operator delete(p);
  }
  template <class U>
  bool operator==(const Skeleton_allocator<U>&) const noexcept
  {
    return true;
  }
  template <class U>
  bool operator!=(const Skeleton_allocator<U>&) const noexcept
  {
    return false;
  }
};

} // namespace internal
} // namespace MPM
} // namespace CGAL

#undef CGAL_ALLOCATOR
#define CGAL_ALLOCATOR(T) CGAL::MPM::internal::Skeleton_allocator<T>
#include <CGAL/HalfedgeDS_default.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/extract_mean_curvature_flow_skeleton.h>

static_assert(std::is_same<CGAL::Polyhedron_3<CGAL::Epick>,
                           CGAL::Polyhedron_3<CGAL::Epick, CGAL::Polyhedron_items_3, CGAL::HalfedgeDS_default,
                                              CGAL::MPM::internal::Skeleton_allocator<int>>>::value,
              "the skeletonization's polyhedron must use the skeleton's allocator: include "
              "Polyhedron_3.h only after CGAL_ALLOCATOR is redefined");

namespace CGAL {
namespace MPM {
namespace internal {

Curve_skeleton curve_skeleton(const Indexed_mesh& mesh, const std::string& source)
{
  using Skeletonization = CGAL::Mean_curvature_flow_skeletonization<Indexed_surface_mesh>;
  const Indexed_surface_mesh surface = to_surface_mesh(mesh, source, "joint cutting");
  Skeletonization::Skeleton skeleton;
  {
    // The skeletonization's polyhedron lives and dies within this scope.
    Skeleton_arena arena;
    try {
      CGAL::extract_mean_curvature_flow_skeleton(surface, skeleton);
    } catch(const std::exception& e) {
      throw Input_error(source, "curve skeleton", std::string("CGAL's skeletonization failed: ") + e.what());
    }
  }
  Curve_skeleton r;
  r.node_of_vertex.assign(std::size_t(mesh.number_of_vertices()), -1);
  for(auto node : CGAL::make_range(boost::vertices(skeleton))) {
    const auto& p = skeleton[node].point;
    r.points.emplace_back(p.x(), p.y(), p.z());
    r.neighbours.emplace_back();
    for(auto v : skeleton[node].vertices) r.node_of_vertex[std::size_t(v)] = int(node);
  }
  for(auto e : CGAL::make_range(boost::edges(skeleton))) {
    const int a = int(boost::source(e, skeleton)), b = int(boost::target(e, skeleton));
    r.neighbours[std::size_t(a)].push_back(b);
    r.neighbours[std::size_t(b)].push_back(a);
  }
  if(boost::num_edges(skeleton) == 0)
    throw Input_error(source, "curve skeleton",
                      "has no edge: the mesh is too coarse or too compact to have a limb axis");
  return r;
}

} // namespace internal
} // namespace MPM
} // namespace CGAL
