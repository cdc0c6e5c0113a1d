#include "panels/WeightsPanel.h"

#include <QCheckBox>
#include <QGroupBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QTableWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <algorithm>

#include "UserAction.h"
#include "base/Error.h"
#include "model/BoneDisplayName.h"
#include "model/CountText.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/commands/SetBoneLockCommand.h"
#include "part/BoneWeights.h"
#include "viewport/Viewport.h"

namespace rigmesh::widgets {

namespace {

constexpr int kBoneIdRole = Qt::UserRole;
constexpr int kVerticesRole = Qt::UserRole + 1;
// Check Rig lists at most this many vertices per finding as rows (all of
// them are marked in the viewport).
constexpr int kListedVertices = 200;

QTableWidget* makeTable(QWidget* parent, const QStringList& headers, const char* name) {
    auto* table = new QTableWidget(0, headers.size(), parent);
    table->setObjectName(QString::fromLatin1(name));
    table->setHorizontalHeaderLabels(headers);
    table->verticalHeader()->setVisible(false);
    table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    for (int c = 1; c < headers.size(); ++c)
        table->horizontalHeader()->setSectionResizeMode(c, QHeaderView::ResizeToContents);
    table->setSelectionBehavior(QAbstractItemView::SelectRows);
    table->setSelectionMode(QAbstractItemView::SingleSelection);
    table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    table->setMinimumWidth(120);  // a narrow dock stays narrow
    table->setSizeAdjustPolicy(QAbstractScrollArea::AdjustIgnored);
    return table;
}

QTableWidgetItem* readOnly(const QString& text) {
    auto* item = new QTableWidgetItem(text);
    item->setFlags(Qt::ItemIsEnabled | Qt::ItemIsSelectable);
    return item;
}

}  // namespace

WeightsPanel::WeightsPanel(QWidget* parent) : QWidget(parent) {
    auto* layout = new QVBoxLayout(this);
    title_ = new QLabel(this);
    title_->setStyleSheet(QStringLiteral("font-weight: bold"));
    title_->setWordWrap(true);
    layout->addWidget(title_);
    notes_ = new QLabel(this);
    notes_->setObjectName(QStringLiteral("weightNotes"));
    notes_->setWordWrap(true);
    notes_->setStyleSheet(QStringLiteral("color: #b35c00"));
    notes_->hide();
    layout->addWidget(notes_);

    bones_ = makeTable(this, {tr("Bone"), tr("Leads"), tr("Lock")}, "weightBones");
    bones_->setToolTip(
        tr("Leads: the vertices whose largest weight is the bone's. Lock: painting and the "
           "clean-ups keep the bone's weights. Click a bone to paint or view it."));
    bones_->setMinimumHeight(150);
    layout->addWidget(bones_, 3);
    connect(bones_, &QTableWidget::cellClicked, this,
            [this](int row, int) { boneRowClicked(row); });
    connect(bones_, &QTableWidget::itemChanged, this, [this](QTableWidgetItem* item) {
        if (!refreshing_ && item->column() == 2)
            boneLockToggled(item->row());
    });

    auto* vertexBox = new QGroupBox(tr("Vertex"), this);
    auto* vertexLayout = new QVBoxLayout(vertexBox);
    vertexTitle_ = new QLabel(vertexBox);
    vertexTitle_->setWordWrap(true);
    vertex_ = makeTable(vertexBox, {tr("Bone"), tr("Weight"), tr("Locked")}, "weightVertex");
    vertexLayout->addWidget(vertexTitle_);
    vertex_->setMinimumHeight(80);
    vertexLayout->addWidget(vertex_);
    layout->addWidget(vertexBox, 1);

    auto* checkBox = new QGroupBox(tr("Check Rig"), this);
    auto* checkLayout = new QVBoxLayout(checkBox);
    auto* row = new QHBoxLayout;
    auto* run = new QPushButton(tr("Check Rig"), checkBox);
    run->setObjectName(QStringLiteral("checkRigButton"));
    maxInfluences_ = new QSpinBox(checkBox);
    maxInfluences_->setRange(1, 64);
    maxInfluences_->setValue(4);
    maxInfluences_->setPrefix(tr("at most "));
    maxInfluences_->setSuffix(tr(" bones"));
    maxInfluences_->setToolTip(tr("Vertices weighted by more bones are listed (glTF takes 4)"));
    row->addWidget(run);
    row->addWidget(maxInfluences_);
    checkLayout->addLayout(row);
    check_ = new QTreeWidget(checkBox);
    check_->setObjectName(QStringLiteral("checkRigResults"));
    check_->setHeaderHidden(true);
    checkLayout->addWidget(check_);
    layout->addWidget(checkBox, 2);
    connect(run, &QPushButton::clicked, this, &WeightsPanel::checkRig);
    connect(check_, &QTreeWidget::itemClicked, this,
            [this](QTreeWidgetItem* item) { checkItemClicked(item); });
    setDocument(nullptr, nullptr);
}

void WeightsPanel::setDocument(model::Document* document, Viewport* viewport) {
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    if (viewport_)
        disconnect(viewport_, nullptr, this, nullptr);
    document_ = document;
    viewport_ = viewport;
    check_->clear();
    checkedPart_ = model::kNoPart;
    if (document_) {
        connect(document_, &model::Document::selectionChanged, this, [this] {
            refreshBones();
            refreshVertex();
        });
        connect(document_, &model::Document::partChanged, this, [this] {
            refreshBones();
            refreshVertex();
        });
        connect(document_, &model::Document::partRemoved, this, [this] {
            refreshBones();
            refreshVertex();
        });
    }
    if (viewport_)
        connect(viewport_, &Viewport::inspectedVertexChanged, this, &WeightsPanel::refreshVertex);
    refreshBones();
    refreshVertex();
}

const model::PartNode* WeightsPanel::selectedNode() const {
    if (!document_)
        return nullptr;
    const model::PartNode* node = document_->findPart(document_->selection().part);
    return node && node->part ? node : nullptr;
}

void WeightsPanel::refreshBones() {
    refreshing_ = true;
    const QSignalBlocker block(bones_);
    bones_->setRowCount(0);
    const model::PartNode* node = selectedNode();
    if (!node || node->part->skeleton.boneCount() == 0) {
        title_->setText(node ? tr("%1 has no skeleton").arg(node->name)
                             : tr("Select a part to see its bones' weights"));
        notes_->hide();
        refreshing_ = false;
        return;
    }
    const Part& part = *node->part;
    const std::map<BoneId, int> leading = leadingVertexCounts(part.weights.perVertex);
    const std::optional<BoneId> selectedBone =
        boneForJoint(part.skeleton, document_->selection().joint);
    title_->setText(tr("%1: %2, %3 locked")
                        .arg(node->name, model::countText(part.skeleton.boneCount(), tr("1 bone"),
                                                          tr("%1 bones")))
                        .arg(part.lockedBones.size()));
    // What the solver fell back on (rig/BoneHeatSolver.h), in the user's language.
    QStringList notes;
    for (Message warning : part.weights.warnings) {
        // The solver numbers the bones that fell back by position; the
        // panel names them as its bone list does.
        const bool namesBones = warning.id == MessageId::WeightsBoneUnsolved ||
                                warning.id == MessageId::WeightsBonesUnsolved;
        if (namesBones && !part.weights.failedBones.empty()) {
            QStringList names;
            for (const BoneId bone : part.weights.failedBones)
                names << model::boneDisplayName(part, bone);
            warning.args = {names.join(QStringLiteral(", ")).toStdString()};
        }
        notes << model::messageText(warning);
    }
    notes_->setText(notes.join(QLatin1Char('\n')));
    notes_->setVisible(!notes.isEmpty());
    bones_->setRowCount(part.skeleton.boneCount());
    for (int b = 0; b < part.skeleton.boneCount(); ++b) {
        const BoneId id = part.skeleton.bones()[b].id;
        auto* name = readOnly(model::boneDisplayName(part, id));
        name->setData(kBoneIdRole, id);
        bones_->setItem(b, 0, name);
        const auto leads = leading.find(id);
        auto* count = readOnly(QString::number(leads == leading.end() ? 0 : leads->second));
        count->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        bones_->setItem(b, 1, count);
        auto* lock = new QTableWidgetItem;
        lock->setFlags(Qt::ItemIsEnabled | Qt::ItemIsUserCheckable | Qt::ItemIsSelectable);
        lock->setCheckState(part.lockedBones.contains(id) ? Qt::Checked : Qt::Unchecked);
        bones_->setItem(b, 2, lock);
        if (selectedBone == id)
            bones_->selectRow(b);
    }
    refreshing_ = false;
}

void WeightsPanel::refreshVertex() {
    const QSignalBlocker block(vertex_);
    vertex_->setRowCount(0);
    const auto inspected = viewport_ ? viewport_->inspectedVertex() : std::nullopt;
    const model::PartNode* node =
        inspected && document_ ? document_->findPart(inspected->part) : nullptr;
    if (!node || !node->part || inspected->vertex >= node->part->mesh.vertexCount()) {
        vertexTitle_->setText(
            tr("Click a vertex with a weight view on (or Ctrl + click while painting) to pin its "
               "weights here."));
        return;
    }
    const Part& part = *node->part;
    const int v = inspected->vertex;
    auto weights = v < static_cast<int>(part.weights.perVertex.size())
                       ? part.weights.perVertex[v]
                       : std::vector<std::pair<BoneId, double>>{};
    std::sort(weights.begin(), weights.end(),
              [](const auto& a, const auto& b) { return a.second > b.second; });
    double sum = 0.0;
    for (const auto& entry : weights)
        sum += entry.second;
    vertexTitle_->setText(
        tr("Vertex %1 of %2: %n bone(s), sum %3", nullptr, static_cast<int>(weights.size()))
            .arg(v)
            .arg(node->name)
            .arg(sum, 0, 'f', 6));
    vertex_->setRowCount(static_cast<int>(weights.size()));
    for (int r = 0; r < static_cast<int>(weights.size()); ++r) {
        const BoneId id = weights[r].first;
        vertex_->setItem(r, 0, readOnly(model::boneDisplayName(part, id)));
        auto* weight = readOnly(QString::number(weights[r].second, 'f', 4));
        weight->setTextAlignment(Qt::AlignRight | Qt::AlignVCenter);
        vertex_->setItem(r, 1, weight);
        vertex_->setItem(r, 2, readOnly(part.lockedBones.contains(id) ? tr("locked") : QString()));
    }
}

void WeightsPanel::boneRowClicked(int row) {
    const model::PartNode* node = selectedNode();
    QTableWidgetItem* item = bones_->item(row, 0);
    if (!node || !item)
        return;
    const BoneId id = item->data(kBoneIdRole).toUInt();
    if (node->part->skeleton.hasBone(id))
        document_->setSelection({node->id, node->part->skeleton.bone(id).tail});
}

void WeightsPanel::boneLockToggled(int row) {
    const model::PartNode* node = selectedNode();
    QTableWidgetItem* name = bones_->item(row, 0);
    QTableWidgetItem* lock = bones_->item(row, 2);
    if (!node || !name || !lock)
        return;
    const BoneId id = name->data(kBoneIdRole).toUInt();
    const bool locked = lock->checkState() == Qt::Checked;
    runUserAction(
        tr("Lock"),
        [this](const QString& failure) {
            emit statusMessage(failure, 6000);
            refreshBones();
        },
        [&] {
            auto command = model::SetBoneLockCommand::create(*document_, node->id, id, locked);
            const QString text = command->text();
            model::pushCommand(*document_, std::move(command));
            emit statusMessage(text, 4000);
        });
}

void WeightsPanel::checkRig() {
    check_->clear();
    if (viewport_)
        viewport_->setMarkedVertices(model::kNoPart, {});
    const model::PartNode* node = selectedNode();
    if (!node) {
        emit statusMessage(tr("Select a part to check its rig"), 4000);
        return;
    }
    RigCheckOptions options;
    options.maxInfluences = maxInfluences_->value();
    const RigCheckReport report = rigmesh::checkRig(*node->part, options);
    checkedPart_ = node->id;
    const Part& part = *node->part;
    auto addVertices = [&](const QString& title, const std::vector<int>& vertices) {
        auto* group = new QTreeWidgetItem(check_, {title});
        group->setData(0, kVerticesRole,
                       QVariant::fromValue(QList<int>(vertices.begin(), vertices.end())));
        for (std::size_t i = 0; i < vertices.size() && i < std::size_t(kListedVertices); ++i) {
            auto* item = new QTreeWidgetItem(group, {tr("Vertex %1").arg(vertices[i])});
            item->setData(0, kVerticesRole, QVariant::fromValue(QList<int>{vertices[i]}));
        }
        if (vertices.size() > std::size_t(kListedVertices))
            new QTreeWidgetItem(group, {tr("... and %1 more (all marked when the group is clicked)")
                                            .arg(vertices.size() - kListedVertices)});
    };
    addVertices(tr("Unweighted vertices: %1").arg(report.unweightedVertices.size()),
                report.unweightedVertices);
    auto* bones = new QTreeWidgetItem(
        check_, {tr("Bones leading no vertex: %1").arg(report.bonesLeadingNoVertex.size())});
    for (BoneId id : report.bonesLeadingNoVertex) {
        auto* item = new QTreeWidgetItem(bones, {model::boneDisplayName(part, id)});
        item->setData(0, kBoneIdRole, id);
    }
    addVertices(tr("Vertices over %1 influences: %2")
                    .arg(options.maxInfluences)
                    .arg(report.verticesOverInfluences.size()),
                report.verticesOverInfluences);
    addVertices(
        tr("Vertices whose weights do not sum to 1: %1").arg(report.verticesWithSumsOff.size()),
        report.verticesWithSumsOff);
    emit statusMessage(
        report.clean()
            ? tr("Check Rig: %1 is clean").arg(node->name)
            : tr("Check Rig found problems in %1: click a line to select them").arg(node->name),
        8000);
}

void WeightsPanel::checkItemClicked(QTreeWidgetItem* item) {
    if (!document_ || !document_->contains(checkedPart_))
        return;
    const model::PartNode& node = document_->part(checkedPart_);
    if (item->data(0, kBoneIdRole).isValid()) {
        const BoneId id = item->data(0, kBoneIdRole).toUInt();
        if (node.part && node.part->skeleton.hasBone(id))
            document_->setSelection({node.id, node.part->skeleton.bone(id).tail});
        return;
    }
    const QList<int> vertices = item->data(0, kVerticesRole).value<QList<int>>();
    if (vertices.isEmpty() || !viewport_)
        return;
    viewport_->setMarkedVertices(node.id, std::vector<int>(vertices.begin(), vertices.end()));
    if (vertices.size() == 1)
        viewport_->setInspectedVertex(Viewport::SurfaceHit{node.id, vertices.front()});
}

}  // namespace rigmesh::widgets
