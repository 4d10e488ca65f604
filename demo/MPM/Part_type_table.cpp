// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "Part_type_table.h"

#include "Session.h"

#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QTableWidget>
#include <QVBoxLayout>

namespace mpm_demo {

bool edit_part_types(QWidget* parent, Session& session)
{
  Raw_mesh_cutting* cutting = session.cutting();
  if(!cutting) return false;
  const CGAL::MPM::Part_type_proposal& proposal = cutting->part_types();
  QDialog dialog(parent);
  dialog.setWindowTitle("Part types");
  QVBoxLayout* layout = new QVBoxLayout(&dialog);
  layout->addWidget(new QLabel("Segments with the same type share a learned shape space. Edit a type to regroup.",
                               &dialog));
  QTableWidget* table = new QTableWidget(int(proposal.segments.size()), 6, &dialog);
  table->setHorizontalHeaderLabels({"label", "faces", "seams", "depth", "type", "split off because"});
  for(int row = 0; row < int(proposal.segments.size()); ++row)
  {
    const CGAL::MPM::Segment_proposal& s = proposal.segments[std::size_t(row)];
    const QStringList cells = {QString::number(s.label), QString::number(s.faces), QString::number(s.seam_loops),
                               QString::number(s.depth), QString::fromStdString(s.type),
                               QString::fromStdString(s.reason)};
    for(int column = 0; column < cells.size(); ++column)
    {
      QTableWidgetItem* item = new QTableWidgetItem(cells[column]);
      if(column != 4) item->setFlags(item->flags() & ~Qt::ItemIsEditable);
      table->setItem(row, column, item);
    }
  }
  table->horizontalHeader()->setStretchLastSection(true);
  layout->addWidget(table);
  QDialogButtonBox* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, &dialog);
  QObject::connect(buttons, &QDialogButtonBox::accepted, &dialog, &QDialog::accept);
  QObject::connect(buttons, &QDialogButtonBox::rejected, &dialog, &QDialog::reject);
  layout->addWidget(buttons);
  dialog.resize(640, 480);
  if(dialog.exec() != QDialog::Accepted) return false;
  for(int row = 0; row < table->rowCount(); ++row)
  {
    const std::string type = table->item(row, 4)->text().trimmed().toStdString();
    if(type != proposal.segments[std::size_t(row)].type)
      session.set_part_type(table->item(row, 0)->text().toInt(), type);
  }
  return true;
}

} // namespace mpm_demo
