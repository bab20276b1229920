#pragma once
// AddressPanel: addresses you can point at (issue 16, part 3), the content of the Address dock
// (layer 3, GUI). It finds the address of the attractor point under the cursor (for the status
// bar), and selects a sub-copy f_w(A) -- typed as an address "0,1,1", picked by clicking the
// attractor and then a prefix of its address, or for a curve typed as a parameter interval
// "[t0, t1]" -- which the attractor view highlights with its control points S_w P. The
// selection is view state, not a document edit: nothing is saved or undone. The addresses are
// looked up among N^L sampled points f_w(x*) (core ifs/Address.h), recomputed once per edit of
// the item; a hover is a scan of those points (well under a millisecond).
#include "core/ifs/Address.h"
#include <QPointF>
#include <QPointer>
#include <QWidget>
#include <memory>
#include <optional>

class QLabel;
class QLineEdit;

namespace awb {

class AttractorItem;
class AttractorView;
class ItemController;
struct DerivedIfs;

class AddressPanel : public QWidget {
    Q_OBJECT
public:
    AddressPanel(ItemController *controller, AttractorView *view, QWidget *parent = nullptr);
    ~AddressPanel() override;

    // The address of the attractor point nearest to `world` when it is drawn within
    // `maxPixels` of it (and, for a curve with a real parameter, its t); nullopt elsewhere or
    // for items without addresses (surfaces, automata).
    struct Hit {
        Address address;
        std::optional<double> t;
        QPointF point;   // the sampled attractor point found
    };
    std::optional<Hit> addressAt(const QPointF &world, double maxPixels = 8.0);
    // The status bar's part for the cursor at `world` ("address 0,1,1,… t = 0.40625"), or empty.
    QString hoverText(const QPointF &world);

    // Selects "0,1,1" (an address) or "[0.25, 0.5]" (a curve's parameter interval): the view
    // highlights it. False with the reason in *error (also shown in the panel) when the text
    // is not valid for the item drawn; the empty text clears the selection.
    bool select(const QString &text, QString *error = nullptr);
    void clearSelection();
    QString selection() const { return m_selection; }
    // The clicked address whose prefixes are offered as links (select(prefix) on a click).
    void pinAddress(const Address &w);
    const Address &pinnedAddress() const { return m_pinned; }
    // The panel's description of the selection (the S_w P rows, t interval).
    QString details() const;

public slots:
    // The drawn item changed (ItemController::refreshed): a new item drops the selection, an
    // edited one gets it recomputed (the sub-copy follows a dragged control point).
    void refresh();
    // A click on the attractor: pins its address and selects a prefix of it (of the length
    // selected before, 3 at first).
    void clickedAt(const QPointF &world);

signals:
    void selectionChanged(const QString &selection);

private:
    // The sampled points of the item drawn now (recomputed after an edit); false when the item
    // has no addresses.
    bool ensureSamples();
    bool apply(const QString &text, QString *error);
    void showPinned();

    ItemController *m_controller;
    AttractorView *m_view;
    QLineEdit *m_edit = nullptr;
    QLabel *m_prefixes = nullptr;
    QLabel *m_details = nullptr;
    QPointer<AttractorItem> m_item;
    std::shared_ptr<const DerivedIfs> m_derived;
    std::unique_ptr<AddressedPoints> m_samples;
    std::vector<ParameterInterval> m_pieces;
    QString m_meaning;
    QString m_selection;
    Address m_pinned;
    int m_selectedLength = 3;
};

} // namespace awb
