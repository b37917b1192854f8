#pragma once
// A Mesh as bytes and back (core/io/bytes.h): how the meshing child hands its meshes to the
// process that asked for them (core/mesh/meshing_child.h).
#include "core/io/bytes.h"
#include "core/mesh/mesh.h"

namespace thinlayer {

void put(ByteWriter& w, const Mesh& m);
void get(ByteReader& r, Mesh& m);

}  // namespace thinlayer
