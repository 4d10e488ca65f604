// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Python `Synthetic` object: a synthetic family member and its ground
// truth. `learn()` takes one directly.
#ifndef CGAL_MPM_PYTHON_SYNTHETIC_H
#define CGAL_MPM_PYTHON_SYNTHETIC_H

#include <CGAL/MPM/Synthetic/Synthetic_model.h>

#include <utility>

namespace mpm_python {

/// A synthetic model as Python holds it.
class Synthetic
{
public:
  /// Takes the model.
  explicit Synthetic(CGAL::MPM::Synthetic_model model) : model_(std::move(model)) {}
  /// The model.
  const CGAL::MPM::Synthetic_model& model() const { return model_; }

private:
  CGAL::MPM::Synthetic_model model_;
};

} // namespace mpm_python

#endif
