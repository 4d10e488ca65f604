// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mpm_demo: interactive editing with a morphable part model, and a batch
// mode (`mpm_demo --batch SCRIPT`) that runs the same edits from a script
// and writes screenshots, for tests and the manual's figures.
#include "Batch_script.h"
#include "Main_window.h"

#include <CGAL/Qt/init_ogl_context.h>

#include <QApplication>
#include <QStatusBar>

#include <iostream>
#include <stdexcept>
#include <string>

namespace mpm_demo {

namespace {

const char* const usage_text =
  "usage: mpm_demo [--synth FAMILY] [--vertices N] [--seed N]\n"
  "                [--model FILE.mpm | --mesh MESH [--labels SEG|components] [--annotation A.json]]\n"
  "                [--batch SCRIPT] [--size WxH] [--help]\n"
  "Without a source it opens the synthetic hand. --batch runs SCRIPT (doc/MPM/Demo.md)\n"
  "without interaction and exits: 0 when every command succeeded, 1 on the first\n"
  "error (named by its line), 2 for a bad command line.\n";

} // namespace

} // namespace mpm_demo

int main(int argc, char** argv)
{
  using namespace mpm_demo;
  CGAL::Qt::init_ogl_context(4, 3);
  QApplication app(argc, argv);
  app.setApplicationName("mpm_demo");

  std::string batch, family = "hand", model, mesh, labels = "components", annotation;
  int vertices = default_synthetic_vertices, width = 0, height = 0;
  unsigned seed = 1;
  const QStringList args = app.arguments();
  try
  {
    for(int i = 1; i < args.size(); ++i)
    {
      const std::string a = args[i].toStdString();
      const auto value = [&]() -> std::string {
        if(i + 1 >= args.size()) throw std::invalid_argument("option " + a + " needs a value");
        return args[++i].toStdString();
      };
      if(a == "--help" || a == "-h")
      {
        std::cout << usage_text;
        return 0;
      }
      else if(a == "--batch") batch = value();
      else if(a == "--synth") family = value();
      else if(a == "--vertices") vertices = std::stoi(value());
      else if(a == "--seed") seed = unsigned(std::stoul(value()));
      else if(a == "--model") model = value();
      else if(a == "--mesh") mesh = value();
      else if(a == "--labels") labels = value();
      else if(a == "--annotation") annotation = value();
      else if(a == "--size")
      {
        const std::string s = value();
        const std::size_t x = s.find('x');
        if(x == std::string::npos) throw std::invalid_argument("--size takes WIDTHxHEIGHT");
        width = std::stoi(s.substr(0, x));
        height = std::stoi(s.substr(x + 1));
      }
      else throw std::invalid_argument("unknown option '" + a + "'");
    }
  }
  catch(const std::exception& e)
  {
    std::cerr << "mpm_demo: " << e.what() << "\n" << usage_text;
    return 2;
  }

  Session session;
  Main_window window(session);
  if(batch.empty() && width == 0) window.resize(1280, 800);
  if(!batch.empty() && width == 0)
  {
    width = 640;
    height = 480;
  }
  if(width > 0) window.viewer().setFixedSize(width, height);
  window.show();
  QApplication::processEvents();

  // A batch script loads its own model; otherwise start with something to drag.
  try
  {
    if(!model.empty()) session.load_model(model);
    else if(!mesh.empty()) session.load_labeled_mesh(mesh, labels, annotation);
    else if(batch.empty()) session.load_synthetic(family, vertices, seed);
  }
  catch(const std::exception& e)
  {
    if(!batch.empty())
    {
      std::cerr << "mpm_demo: " << e.what() << "\n";
      return 1;
    }
    window.statusBar()->showMessage(QString("Error: ") + e.what());
  }

  if(!batch.empty()) return run_batch_script(session, window, batch);
  window.viewer().set_view(0., 20.);
  return app.exec();
}
