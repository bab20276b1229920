#pragma once
// Starting meshes (issue 30/31): the polyhedra every subdivision course begins with, an open
// grid, and grids whose quads are split along mixed diagonals, which give interior valences 4
// to 8 and a boundary. The tests, the bundled examples and Item > Add > Mesh surface take them
// from here. Faces counter-clockwise seen from outside (from +z for the grids).

#include "core/mesh/Mesh.h"

#include <string>
#include <vector>

namespace awb {

Mesh cubeMesh();             // 8 vertices of valence 3, 6 quads, corners at +-1
Mesh tetrahedronMesh();      // 4 vertices of valence 3
Mesh octahedronMesh();       // 6 vertices of valence 4
Mesh icosahedronMesh();      // 12 vertices of valence 5
Mesh pentagonalPrismMesh();  // two pentagons and five quads
// w x h unit quads (or each split in two triangles along the same diagonal), z = sin(1.3 x +
// 0.7 y).
Mesh gridMesh(int w, int h, bool triangles);
// w x h quads, each split along one of its two diagonals chosen by `seed` (a hash, the same
// on every machine), z bumped: interior valences 4 to 8.
Mesh diagonalGridMesh(int w, int h, unsigned seed);

// A UV sphere of radius 1: `segments` meridians, `rings` bands, triangles around its two poles
// (valence `segments`), quads between; faces counter-clockwise from outside.
Mesh uvSphereMesh(int segments, int rings);
// A torus (radii 3 and 1) of n x m quads, or each split in two triangles (interior valence 6).
Mesh torusMesh(int n, int m, bool triangles);

// Turns every face of a mesh around its centre outward (convex polyhedra).
void orientOutward(Mesh &mesh);

// The names of the starting meshes ("cube", "tetrahedron", "octahedron", "icosahedron",
// "pentagonal-prism", "grid", "diagonal-grid"), and one by name (InputError otherwise).
const std::vector<std::string> &exampleMeshNames();
Mesh exampleMesh(const std::string &name);

} // namespace awb
