#include "WeightViewChooser.h"

#include <QAction>
#include <QActionGroup>
#include <QComboBox>
#include <QLabel>
#include <QMainWindow>
#include <QMenu>
#include <QSignalBlocker>
#include <QToolBar>
#include <utility>

#include "viewport/RenderScene.h"

namespace rigmesh::widgets {

WeightViewChooser::WeightViewChooser(QMenu* viewMenu, QMainWindow* window)
    : QObject(window), group_(new QActionGroup(this)) {
    QMenu* menu = viewMenu->addMenu(tr("&Weights"));
    const std::pair<QString, WeightView> views[] = {
        {tr("&Off"), WeightView::Off},
        {tr("&Selected Bone (select its joint)"), WeightView::SelectedBone},
        {tr("&Dominant Bone"), WeightView::DominantBone},
        {tr("&Influence Count"), WeightView::Influences},
        {tr("Difference from &Global Weights"), WeightView::GlobalDifference}};
    for (const auto& [text, view] : views) {
        QAction* action = menu->addAction(text);
        action->setCheckable(true);
        action->setChecked(view == WeightView::Off);
        action->setData(static_cast<int>(view));
        group_->addAction(action);
        connect(action, &QAction::triggered, this, [this, view = view] {
            show(view);
            emit chosen(view);
        });
    }

    auto* bar = window->addToolBar(tr("Weight View"));
    bar->setObjectName(QStringLiteral("weightViewToolBar"));
    bar->addWidget(new QLabel(tr(" Weights: "), bar));
    box_ = new QComboBox(bar);
    box_->setObjectName(QStringLiteral("weightViewBox"));
    box_->setToolTip(tr("Colour the surface by its skin weights (View > Weights)"));
    for (QAction* action : group_->actions())
        box_->addItem(action->text().remove(QLatin1Char('&')), action->data());
    bar->addWidget(box_);
    connect(box_, &QComboBox::activated, this,
            [this](int index) { choose(static_cast<WeightView>(box_->itemData(index).toInt())); });
}

void WeightViewChooser::show(WeightView view) {
    for (QAction* action : group_->actions())
        if (static_cast<WeightView>(action->data().toInt()) == view)
            action->setChecked(true);
    const QSignalBlocker block(box_);
    box_->setCurrentIndex(box_->findData(static_cast<int>(view)));
}

void WeightViewChooser::choose(WeightView view) {
    for (QAction* action : group_->actions())
        if (static_cast<WeightView>(action->data().toInt()) == view)
            action->trigger();
}

}  // namespace rigmesh::widgets
