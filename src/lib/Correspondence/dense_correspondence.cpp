// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <CGAL/MPM/Correspondence/Dense_correspondence.h>
#include <CGAL/MPM/Input_error.h>
#include <CGAL/MPM/Model/Shape_space.h>
#include <CGAL/MPM/internal/Correspondence_surface.h>
#include <CGAL/MPM/internal/Message_text.h>

#include <cstdio>
#include <limits>
#include <memory>

namespace CGAL {
namespace MPM {

using namespace internal::correspondence;
using internal::percent;

namespace {

// Segments this many times longer (along their axis) than wide (their
// first loop's radius) are also placed along the tube.
constexpr double tube_slenderness = 3.;

std::string mirror_warning(const std::string& element, const std::string& segment, const std::string& template_name,
                           double residual, double mirrored_residual)
{
  return segment + " (" + element + ") looks like a mirror image of the template " + template_name +
         ": the mirrored template would cover it to " + percent(mirrored_residual) +
         " of its diagonal, the orientation-preserving fit kept only to " + percent(residual) +
         "; a reflection would turn the part inside out, so it keeps its own orientation. Give it a part type of its "
         "own (a left and a right limb) or landmarks to fit it better";
}

std::string flipped_warning(const std::string& element, const std::string& segment, int flipped, std::size_t faces,
                            double residual)
{
  return segment + " (" + element + "): " + std::to_string(flipped) + " of " + std::to_string(faces) +
         " template triangles (" + percent(double(flipped) / std::max<std::size_t>(1, faces)) +
         ") face against the segment's surface (coverage residual " + percent(residual) +
         " of its diagonal): the correspondence folds there";
}

} // namespace

std::vector<std::vector<int>> boundary_loops(const Indexed_mesh& mesh)
{
  std::vector<Loop> loops;
  for(std::vector<int>& vertices : loops_of(mesh)) loops.push_back(make_loop(mesh.points, std::move(vertices)));
  std::sort(loops.begin(), loops.end(), [](const Loop& a, const Loop& b) { return a.length() > b.length(); });
  std::vector<std::vector<int>> r;
  for(Loop& l : loops) r.push_back(std::move(l.vertices));
  return r;
}

Dense_correspondence compute_dense_correspondence(const std::vector<Correspondence_segment>& segments,
                                                  const std::string& type_name,
                                                  const Dense_correspondence_options& options)
{
  const std::string element = "part type \"" + type_name + "\"";
  if(segments.empty()) throw Input_error("", element, "no segment to put in correspondence");
  const auto progress = [&](const std::string& stage, double fraction) {
    internal::throw_if_cancelled(options.cancel, "correspondence");
    if(options.progress) options.progress(stage, fraction);
  };
  Dense_correspondence result;
  const auto warn = [&](const std::string& message) {
    result.warnings.push_back(message);
    if(options.warning) options.warning(message);
  };
  const std::size_t m = segments.size();
  for(std::size_t i = 0; i < m; ++i)
  {
    const Correspondence_segment& s = segments[i];
    for(std::size_t k = 0; k < s.landmarks.size(); ++k)
      if(s.landmarks[k] < 0 || s.landmarks[k] >= s.mesh.number_of_vertices())
        throw Input_error(s.name, element + ": landmark " + std::to_string(k),
                          "vertex " + std::to_string(s.landmarks[k]) + " is out of range (the segment has " +
                            std::to_string(s.mesh.number_of_vertices()) + " vertices)");
    if(s.landmarks.size() != segments.front().landmarks.size())
      throw Input_error(s.name, element,
                        std::to_string(s.landmarks.size()) + " landmarks but " + segments.front().name + " has " +
                          std::to_string(segments.front().landmarks.size()) +
                          "; every segment of a type needs the same landmarks");
  }
  std::vector<std::unique_ptr<Surface>> surfaces;
  for(const Correspondence_segment& s : segments)
  {
    surfaces.push_back(std::make_unique<Surface>(s.mesh, type_name, s.name));
    tag_loops(*surfaces.back(), s.seam_tags);
  }
  for(std::size_t i = 1; i < m; ++i)
    if(surfaces[i]->loops.size() != surfaces[0]->loops.size())
      throw Input_error(segments[i].name, element,
                        "has " + std::to_string(surfaces[i]->loops.size()) + " boundary loops but " +
                          segments[0].name + " has " + std::to_string(surfaces[0]->loops.size()) +
                          "; segments of one type must have the same seams");

  const Surface& t = *surfaces[0];
  const Template_info info = make_template_info(t);
  // The template reflected through x = 0, triangles reversed so that it
  // stays consistently oriented.
  Indexed_mesh mirrored_template = t.mesh;
  mirrored_template.points.col(0) *= -1.;
  for(Triangle& f : mirrored_template.triangles) std::swap(f[1], f[2]);
  Surface mirror(mirrored_template, type_name, segments[0].name);
  tag_loops(mirror, segments[0].seam_tags);
  const Template_info mirror_info = make_template_info(mirror);
  result.triangles = t.mesh.triangles;
  result.segments.resize(m);
  result.segments[0].positions = result.segments[0].unrefined = t.mesh.points;

  // Most deviating (bounding-box diagonal) from the segments done first.
  std::vector<int> order{0};
  std::vector<bool> done(m, false);
  done[0] = true;
  while(order.size() < m)
  {
    int next = -1;
    double best = -1.;
    for(std::size_t i = 0; i < m; ++i)
    {
      if(done[i]) continue;
      double deviation = std::numeric_limits<double>::infinity();
      for(int j : order) deviation = std::min(deviation, std::abs(surfaces[i]->diagonal - surfaces[j]->diagonal));
      if(deviation > best)
      {
        best = deviation;
        next = static_cast<int>(i);
      }
    }
    done[next] = true;
    order.push_back(next);
  }

  std::vector<Landmarks> landmarks(m);
  std::vector<Point_matrix> positions(m);
  std::vector<double> unrefined_residual(m, 0.);
  positions[0] = t.mesh.points;
  for(std::size_t rank = 1; rank < m; ++rank)
  {
    const int i = order[rank];
    progress("correspondence of " + type_name, double(rank - 1) / m);
    const Surface& s = *surfaces[i];
    Segment_correspondence& r = result.segments[i];
    r.order = static_cast<int>(rank);
    // One attempt with template `tmpl` (the template or its mirror image).
    struct Attempt
    {
      Segment_correspondence r;
      Landmarks lm;
      Point_matrix y;
      double residual = std::numeric_limits<double>::infinity();
    };
    const auto finish = [&](Attempt& a, const Template_info& tinfo, const Point_matrix& coarse) {
      a.y = laplacian_icp(s, tinfo, a.lm, coarse, options, a.r.iterations);
      std::vector<Vec3> frame;
      project(s, tinfo, a.lm, a.y, frame);
      for(const auto& [v, p] : a.lm.vertex_targets) a.y.row(v) = p.transpose();
      a.residual = coverage_residual(s, a.y, t.mesh.triangles);
    };
    const auto attempt = [&](const Surface& tmpl, const Template_info& tinfo, bool use_tilt) {
      Attempt a;
      a.r = r;
      a.lm = match_landmarks(tmpl, s, segments[0].landmarks, segments[i].landmarks, options.loop_samples, use_tilt);
      a.r.automatic_landmarks = a.lm.automatic;
      const Point_matrix base = a.lm.motion.apply(tmpl.mesh.points);
      Point_matrix coarse;
      const bool use_prior = &tmpl == &t && options.prior.number_of_modes() > 0 &&
                             options.prior.mean.rows() == tmpl.mesh.points.rows();
      if(use_prior || (options.segments_before_pca > 0 && int(rank) > options.segments_before_pca))
      {
        Shape_space learned;
        if(!use_prior)
        {
          std::vector<Point_matrix> instances;
          for(std::size_t k = 0; k < rank; ++k) instances.push_back(positions[order[k]]);
          Shape_space_options so;
          so.explained_variance = 1.;
          learned = learn_shape_space(instances, so);
        }
        const Shape_space& space = use_prior ? options.prior : learned;
        const Point_matrix start =
          base + fit_spline(a.lm.motion.apply(a.lm.source), a.lm.target - a.lm.motion.apply(a.lm.source), s.diagonal)
                   .displacement(base);
        coarse = shape_space_icp(s, tinfo, a.lm, space, start, options, a.r.iterations);
        a.r.used_shape_space = true;
      }
      else
        coarse = spline_icp(s, tinfo, a.lm, base, options, a.r.iterations);
      finish(a, tinfo, coarse);
      return a;
    };
    // A limb bent or curled unlike the template is out of reach of a rigid
    // start and a spline: the template is also placed along the tube.
    const auto along_tube = [&](const Surface& tmpl, const Template_info& tinfo, const Attempt& from) {
      Attempt a;
      a.r = from.r;
      a.lm = from.lm;
      a.r.used_shape_space = false;
      Point_matrix coarse;
      if(tube_chart_start(tmpl, s, a.lm, tube_slenderness, coarse)) finish(a, tinfo, coarse);
      return a;
    };
    // The lean of a lone seam is a cue at a mitred joint but arbitrary at a
    // hand-made cut: with one loop, both are tried and the one covering the
    // segment better wins (the lean on near ties: within a quarter). A poor
    // fit with more loops gets the second try as well.
    const auto best_of = [&](const Surface& tmpl, const Template_info& tinfo) {
      Attempt best = attempt(tmpl, tinfo, true);
      if(tmpl.loops.size() == 1 || best.residual > options.mirror_check_residual)
      {
        Attempt other = attempt(tmpl, tinfo, false);
        other.r.iterations += best.r.iterations;
        if(other.residual < 0.75 * best.residual) best = std::move(other);
      }
      Attempt tube = along_tube(tmpl, tinfo, best);
      tube.r.iterations += best.r.iterations;
      if(tube.residual < best.residual &&
         flipped_faces(s, tube.y, t.mesh.triangles).size() <= flipped_faces(s, best.y, t.mesh.triangles).size())
        best = std::move(tube);
      return best;
    };
    Attempt chosen = best_of(t, info);
    // A poor fit may be a mirror image (a left and a right limb). The
    // mirrored template is tried only to say so: its positions would carry
    // the template's triangles inside out, so the orientation-preserving
    // fit is kept whatever the mirror covers.
    if(chosen.residual > options.mirror_check_residual)
    {
      const Attempt reflected = best_of(mirror, mirror_info);
      if(reflected.residual < 0.75 * chosen.residual)
      {
        chosen.r.mirrored = true;
        warn(mirror_warning(element, segments[i].name, segments[0].name, chosen.residual, reflected.residual));
      }
    }
    r = chosen.r;
    r.unrefined = positions[i] = chosen.y;
    unrefined_residual[i] = chosen.residual;
    landmarks[i] = chosen.lm;
  }

  std::vector<Point_matrix> unrefined = positions;
  if(options.refine && m > 1)
  {
    progress("refinement of " + type_name, double(m - 1) / m);
    result.refinement_iterations = refine(surfaces, landmarks, info, 0, options, positions, result.before, result.after);
    // The refinement lowers the spread of the shapes after a rigid
    // alignment; between a straight and a curled limb it does so by sliding
    // the template off the curl. A segment it leaves much less covered
    // keeps its fit.
    for(std::size_t i = 1; i < m; ++i)
    {
      const double before = unrefined_residual[i];
      if(coverage_residual(*surfaces[i], positions[i], result.triangles) > std::max(1.5 * before, before + 0.002))
        positions[i] = unrefined[i];
    }
  }
  else
  {
    std::vector<const Landmarks*> lm(m, nullptr);
    for(std::size_t i = 1; i < m; ++i) lm[i] = &landmarks[i];
    Alignment alignment;
    result.before = result.after = evaluate(positions, lm, info, alignment);
  }
  for(std::size_t i = 0; i < m; ++i)
  {
    if(i > 0)
    {
      unfold(*surfaces[i], info, landmarks[i], result.triangles, positions[i]);
      unfold_in_chart(*surfaces[i], info, landmarks[i], result.triangles, positions[i]);
      cover_missed_points(*surfaces[i], info, landmarks[i], result.triangles, positions[i]);
    }
    result.segments[i].positions = positions[i];
    result.segments[i].unrefined = unrefined[i];
    result.segments[i].residual = i == 0 ? 0. : coverage_residual(*surfaces[i], positions[i], result.triangles);
    result.segments[i].flipped_faces = static_cast<int>(flipped_faces(*surfaces[i], positions[i], result.triangles).size());
    const double fraction = double(result.segments[i].flipped_faces) / std::max<std::size_t>(1, result.triangles.size());
    if(fraction > options.flipped_warning_fraction)
      warn(flipped_warning(element, segments[i].name, result.segments[i].flipped_faces, result.triangles.size(),
                           result.segments[i].residual));
  }
  progress("correspondence of " + type_name, 1.);
  return result;
}

} // namespace MPM
} // namespace CGAL
