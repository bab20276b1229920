#pragma once
// What the eigenvalues say at one extraordinary vertex of a mesh (issue 31), and the table of
// every valence -- two tabs of the Analysis dock:
//  - VertexPanel: Reif's verdict with its numbers (λ, μ, λ², the spectral criterion, the
//    characteristic map's regularity and injectivity, the curvature), and the characteristic
//    map itself: the n faces around the vertex under the two subdominant eigenvectors, the
//    n-fold star of Peters & Reif, each cell shaded by the sign of its Jacobian;
//  - ValenceChart: λ(n), μ(n) and λ²(n) for n = 3 ... 16 of the current scheme, and μ
//    against λ² (below the diagonal the curvature vanishes, above it is unbounded), with the
//    item's own valences marked.
// Both take plain core data (core/mesh/VertexSpectrum.h, MeshAnalysis.h); Qt Charts stays out
// of this header.

#include "core/mesh/MeshAnalysis.h"
#include "core/mesh/VertexSpectrum.h"

#include <QString>
#include <QWidget>

#include <optional>
#include <vector>

class QChartView;
class QLabel;
class QPainter;
class QPushButton;
class QSplitter;
class QTextBrowser;

namespace awb {

// The characteristic map drawn to fit its widget (or any painter: the figure sheet).
class CharacteristicMapView : public QWidget {
    Q_OBJECT
public:
    explicit CharacteristicMapView(QWidget *parent = nullptr);
    // `valence` 0 with an empty map: nothing to draw (the text says why).
    void setMap(const CharacteristicMap &map, int valence);
    const CharacteristicMap &map() const { return m_map; }
    int valence() const { return m_valence; }
    // Cells whose Jacobian has the other sign than the majority (0 for a regular map).
    int foldedCells() const;
    void paintMap(QPainter &p, const QRectF &target) const;
    QSize sizeHint() const override { return {320, 320}; }
    QSize minimumSizeHint() const override { return {120, 120}; }

protected:
    void paintEvent(QPaintEvent *event) override;

private:
    CharacteristicMap m_map;
    int m_valence = 0;
};

class VertexPanel : public QWidget {
    Q_OBJECT
public:
    explicit VertexPanel(QWidget *parent = nullptr);

    // The vertex shown, with the interior analysis of its valence (its characteristic map);
    // `where` names it for the user ("vertex 3", "the centre of face 2").
    void setVertex(const ExtraordinaryVertex &vertex, MeshScheme scheme,
                   const std::optional<VertexSpectrum> &interior, const QString &where);
    // Nothing chosen: the text says how to choose (or `why` nothing can be).
    void clear(const QString &why = {});
    bool hasVertex() const { return m_has; }
    // The verdict as plain text (tests, the figure sheet).
    QString verdictText() const;
    CharacteristicMapView *mapView() const { return m_map; }
    // The verdict at an extraordinary vertex as HTML.
    static QString verdictHtml(const ExtraordinaryVertex &vertex, MeshScheme scheme,
                               const std::optional<VertexSpectrum> &interior,
                               const QString &where);

signals:
    // "New eigenvalue plot of this vertex".
    void plotRequested();

protected:
    // Text beside the map in a wide panel, above it in a tall one.
    void resizeEvent(QResizeEvent *event) override;

private:
    QSplitter *m_split = nullptr;
    QTextBrowser *m_text = nullptr;
    CharacteristicMapView *m_map = nullptr;
    QPushButton *m_plot = nullptr;
    bool m_has = false;
};


class ValenceChart : public QWidget {
    Q_OBJECT
public:
    explicit ValenceChart(QWidget *parent = nullptr);
    ~ValenceChart() override;
    // The scheme's table (computed once per scheme and kept) and the item's valences (interior
    // extraordinary vertices) to mark.
    void setScheme(MeshScheme scheme, std::vector<int> itemValences);
    // The rows drawn (n = 3 ... 16; empty until the chart is first shown).
    const std::vector<VertexSpectrum> &table() const;
    std::vector<int> markedValences() const { return m_marked; }
    QChartView *valenceView() const { return m_byValence; }
    QChartView *curvatureView() const { return m_curvature; }

    static constexpr int kFrom = 3, kTo = 16;

protected:
    void showEvent(QShowEvent *event) override;
    void resizeEvent(QResizeEvent *event) override;

    // The charts' titles, legends and ticks as laid out for their current size: full where
    // there is room, shorter and sparser in a small dock (issue 47: "… … …", "μ… n… t…").
    void fitToSize();

private:
    void rebuild();

    QSplitter *m_split = nullptr;
    QChartView *m_byValence = nullptr;
    QChartView *m_curvature = nullptr;
    std::optional<MeshScheme> m_scheme;
    std::optional<MeshScheme> m_drawn;
    std::vector<int> m_marked, m_drawnMarked;
    std::vector<VertexSpectrum> m_table;
};

} // namespace awb
