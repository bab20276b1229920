#include "model/MapMatrices.h"

#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"

namespace awb {

int listedMapCount(const DerivedIfs &d)
{
    return d.S.count() > 0 ? d.S.count() : d.ifs.size();
}

MapMatrices mapMatrices(const DerivedIfs &d, int i)
{
    MapMatrices m;
    for (int j = 0; j < d.ifs.size(); ++j)
        if (d.analysisIndex(j) == i)
            m.ifsMap = j;
    if (i < int(d.S.real.size()))
        m.S = d.S.real[size_t(i)];
    else if (i < int(d.S.complex.size()))
        m.complexS = d.S.complex[size_t(i)];
    if (d.subdivision && d.subdivision->lifting.invertible && i < int(d.S.real.size())) {
        const LiftedMap l = liftMatrix(d.subdivision->lifting, d.S.real[size_t(i)]);
        m.M = l.M;
        m.A = l.A;
        m.b = l.b;
        m.eigenvaluesA = spectrum(l.A).values;
    } else if (i < int(d.liftedComplex.size())) {
        const CMat &M = d.liftedComplex[size_t(i)];
        const Eigen::Index n = M.rows() - 1;
        m.complexM = M;
        m.complexA = M.topLeftCorner(n, n);
        m.complexB = M.bottomLeftCorner(1, n);
        m.eigenvaluesA = spectrum(*m.complexA).values;
    } else if (m.ifsMap >= 0) {
        m.A = d.ifs.maps[size_t(m.ifsMap)].A;
        m.b = d.ifs.maps[size_t(m.ifsMap)].b;
        m.eigenvaluesA = spectrum(d.ifs.effectiveLinearPart(m.ifsMap)).values;
    }
    return m;
}

} // namespace awb
