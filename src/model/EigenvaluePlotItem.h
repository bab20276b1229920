#pragma once
// Document item "eigenvalue-plot" (layer 2, model): the spectra of another item's matrices,
// the subdivision matrices S_i, the linear parts A_i of M_i = P^-1 S_i P or the whole lifted
// maps M_i (003 §4, 004 §2.1).
// It stores only which item (by name) and which matrices; the spectra are derived from the
// source's derived IFS and recomputed when the source changes.

#include "core/analysis/Spectrum.h"
#include "model/AttractorItem.h"

namespace awb {

// What an eigenvalue plot derives: the spectrum of each of the source's matrices. Never saved.
struct EigenvalueData {
    QString symbol;                      // "S", "A" or "M"
    bool complexMatrices = false;        // the source has a complex Bézier parameter
    AnalysisMatrices matrices;           // the matrices analysed (S_i, A_i or M_i)
    std::vector<Spectrum> spectra;       // one per map, in map order
    // The subdominant eigenvalues (for S: after the eigenvalue 1 of affine invariance).
    std::vector<Subdominant> subdominants;
};

class EigenvaluePlotItem : public Item {
    Q_OBJECT
public:
    enum class MatrixKind { S, A, M };

    EigenvaluePlotItem();

    static QString staticType() { return QStringLiteral("eigenvalue-plot"); }
    static QString staticTypeName() { return tr("Eigenvalue plot"); }
    QString type() const override { return staticType(); }
    QString typeName() const override { return staticTypeName(); }

    // The name of the item whose matrices are analysed ("" for none yet).
    QString source() const { return m_source; }
    bool setSource(const QString &name);
    // For a mesh source: the extraordinary vertex whose local subdivision matrix is analysed
    // (issue 31) -- an input vertex, or with `face` the centre of a face that is not a quad
    // (Catmull-Clark); -1, -1: the mesh's own matrices (derived S).
    int vertex() const { return m_vertexFace.first; }
    int face() const { return m_vertexFace.second; }
    bool setExtraordinary(int vertex, int face = -1);
    MatrixKind matrixKind() const { return m_matrixKind; }
    bool setMatrixKind(MatrixKind kind);
    // "S", "A", "M" in enum order.
    static const QStringList &matrixKindNames();
    // What each kind is, for the user, in enum order ("S_i, the subdivision matrices", ...).
    static QStringList matrixKindDescriptions();

    // The matrices of kind `kind` of a derived IFS (M_i: the lifted maps, real or complex);
    // none, with the reason in `unavailable`, when the IFS has no such matrices.
    static AnalysisMatrices analysedMatrices(const DerivedIfs &derived, MatrixKind kind);

    // Null when they cannot be computed (no such item, its IFS fails, M_i undefined, ...),
    // with the reason in derivedError().
    std::shared_ptr<const EigenvalueData> eigenvalues() const;
    QString derivedError() const override;
    QStringList references() const override { return {m_source}; }

    // Declared: "source" (an item of the project, by name), "matrices" (S, A or M), and for
    // a mesh source the extraordinary vertex (saved as "vertex" or "face").
    static const PropertyTable &declaration();
    const PropertyTable &properties() const override { return declaration(); }

signals:
    void sourceChanged();
    void matrixKindChanged();
    void extraordinaryChanged();

protected:
    bool dropDerived() override { return m_eigenvalues.drop(); }
    void renameReference(const QString &from, const QString &to) override;

private:
    EigenvalueData compute() const;

    QString m_source;
    MatrixKind m_matrixKind = MatrixKind::S;
    std::pair<int, int> m_vertexFace{-1, -1};
    DerivedCache<EigenvalueData> m_eigenvalues;
};

} // namespace awb
