#pragma once
// The analysis of a mesh item as JSON (issue 30; `attractor-cli analyse --json`, later the
// Python module's item.analyse()): the mesh, every extraordinary vertex with its spectrum and
// verdicts, and the pieces of the IFS with condensation with their maps.

#include "core/mesh/Mesh.h"
#include "model/ItemAnalysisJson.h"

#include <QJsonArray>
#include <QJsonObject>

namespace awb {

class SubdivisionMeshItem;

// "kind", "scheme", "vertex_count", "face_count", "extraordinary": [{"vertex" or "face",
// "valence", "boundary", "eigenvalues" ([re, im] pairs), "subdominant", "subsubdominant",
// "c1", "curvature", "ring", "ring_size", "limit", "normal"}], "pieces": {"isolation_steps",
// "roots", "types": [...]}. Empty when the mesh is refused.
// An interior extraordinary vertex also has "characteristic_map": {"regular", "injective",
// "winding", "min_area", "max_area", "cells"} (Reif's check, VertexSpectrum.h).
// meshAnalysis() gives "extraordinary" as a list (ItemAnalysisJson.h), each vertex's JSON made
// when it is asked for; meshAnalysisJson() fills it in.
ItemAnalysis meshAnalysis(const SubdivisionMeshItem &item);
inline QJsonObject meshAnalysisJson(const SubdivisionMeshItem &item)
{
    return meshAnalysis(item).whole();
}

// The valence explorer's table (issue 31; `attractor-cli valences`): per valence n = from ...
// to, {"valence", "subdominant", "closed_form", "subsubdominant", "lambda_squared",
// "spectral_c1", "characteristic_map": {...}, "c1", "curvature", "ring_size"}.
QJsonArray valenceTableJson(MeshScheme scheme, int from, int to);

} // namespace awb
