// Copyright (c) 2026 CGAL-MPM contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// libFuzzer target: deserialize_model(). The first byte chooses the mode:
// even, the rest is the file as is (magic, header and checksum checks);
// odd, the rest is a payload that gets a valid header and CRC-32 so that
// mutations reach the payload parser and the consistency checks.
#include "fuzz_common.h"

#include <CGAL/MPM/IO/Model_io.h>
#include <CGAL/MPM/Synthetic/Synthetic_model.h>
#include <CGAL/MPM/Learning/learn_morphable_part_model.h>

#include <boost/crc.hpp>

namespace {

void put(std::string& s, std::uint64_t v, int bytes)
{
  for(int i = 0; i < bytes; ++i) s.push_back(char(std::uint8_t(v >> (8 * i))));
}

} // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***)
{
  if(std::getenv("MPM_FUZZ_WRITE_SEED") != nullptr)
  {
    CGAL::MPM::Synthetic_options o;
    o.vertices = 300;
    const auto truth = CGAL::MPM::make_synthetic_model(CGAL::MPM::Synthetic_family::hexa_grid, o);
    const std::string bytes =
      CGAL::MPM::serialize_model(CGAL::MPM::learn_morphable_part_model(truth.mesh, truth.annotation));
    // Mode 1: payload only (header and CRC are rebuilt by the target).
    const std::size_t header = 8 + 4 + 8;
    mpm_fuzz::maybe_write_seed("\x01" + bytes.substr(header, bytes.size() - header - 4));
  }
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  if(size == 0) return 0;
  std::string bytes;
  if(data[0] & 1)
  {
    const char* payload = reinterpret_cast<const char*>(data + 1);
    const std::size_t length = size - 1;
    bytes.assign("CGALMPM\n", 8);
    put(bytes, CGAL::MPM::model_file_version, 4);
    put(bytes, length, 8);
    bytes.append(payload, length);
    boost::crc_32_type crc;
    crc.process_bytes(payload, length);
    put(bytes, crc.checksum(), 4);
  }
  else
    bytes = mpm_fuzz::as_string(data + 1, size - 1);
  mpm_fuzz::expect_input_errors_only([&] {
    const CGAL::MPM::Morphable_part_model m = CGAL::MPM::deserialize_model(bytes, "fuzz.mpm");
    (void)CGAL::MPM::deserialize_model(CGAL::MPM::serialize_model(m), "fuzz round trip");
  });
  return 0;
}
