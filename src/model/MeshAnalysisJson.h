#pragma once
// The analysis of a mesh item as JSON (issue 30; `attractor-cli analyse --json`, later the
// Python module's item.analyse()): the mesh, every extraordinary vertex with its spectrum and
// verdicts, and the pieces of the IFS with condensation with their maps.

#include <QJsonObject>

namespace awb {

class SubdivisionMeshItem;

// "kind", "scheme", "vertex_count", "face_count", "extraordinary": [{"vertex" or "face",
// "valence", "boundary", "eigenvalues" ([re, im] pairs), "subdominant", "subsubdominant",
// "c1", "curvature", "ring", "ring_size", "limit", "normal"}], "pieces": {"isolation_steps",
// "roots", "types": [...]}. Empty when the mesh is refused.
QJsonObject meshAnalysisJson(const SubdivisionMeshItem &item);

} // namespace awb
