#pragma once
// Scene results as bytes, so that a scene solved on one MPI rank can be handed to the others
// (studies/parallel/scene_batch.h). Numbers travel as their exact bit patterns (all ranks run the same
// binary on the same kind of machine), so a result read back equals the one written, bit for
// bit: that is what makes a spread study's file identical to a one-process run's.
//
// put(w, x) appends x; get(r, x) reads it back in the same order (core/io/bytes.h: numbers,
// strings, containers). Every type a study hands over has one overload pair here. A field added to one of these structs must be added to its
// pair too, or a spread study's file silently lacks it (tests/test_scene_batch.cpp round-trips
// them; the CTest mpi_two_ranks_convergence compares the files).
#include "core/io/bytes.h"
#include "core/io/scene_record.h"
#include "core/mesh/layer_band.h"
#include "core/solvers/solve_report.h"
#include "cases/bar/bar_scenes.h"
#include "cases/dovetail/dovetail_scenes.h"
#include "cases/layer_scene.h"
#include "studies/tools/map_cell.h"

namespace thinlayer {

void put(ByteWriter& w, const StatusCount& c);
void get(ByteReader& r, StatusCount& c);
void put(ByteWriter& w, const LayerCounts& c);
void get(ByteReader& r, LayerCounts& c);
void put(ByteWriter& w, const MeshQuality& q);
void get(ByteReader& r, MeshQuality& q);
void put(ByteWriter& w, const SolveReport& s);
void get(ByteReader& r, SolveReport& s);
void put(ByteWriter& w, const InterfaceFields& f);
void get(ByteReader& r, InterfaceFields& f);
void put(ByteWriter& w, const SceneRecord& s);
void get(ByteReader& r, SceneRecord& s);
void put(ByteWriter& w, const BarScene& s);
void get(ByteReader& r, BarScene& s);
void put(ByteWriter& w, const BarLayerScene& s);
void get(ByteReader& r, BarLayerScene& s);
void put(ByteWriter& w, const DovetailScene& s);
void get(ByteReader& r, DovetailScene& s);
void put(ByteWriter& w, const MapCellLevel& c);
void get(ByteReader& r, MapCellLevel& c);
void put(ByteWriter& w, const MapCell& c);
void get(ByteReader& r, MapCell& c);

}  // namespace thinlayer
