#include "timeline/TimelineDock.h"

#include <QComboBox>
#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QInputDialog>
#include <QLabel>
#include <QMenu>
#include <QSpinBox>
#include <QStyle>
#include <QToolButton>
#include <QVBoxLayout>

#include "UserAction.h"
#include "base/Error.h"
#include "model/ClipModes.h"
#include "model/ErrorText.h"
#include "model/GuardedUndo.h"
#include "model/PartClips.h"
#include "model/TimelineItemModel.h"
#include "model/commands/ClipListCommand.h"
#include "model/commands/SetClipSettingsCommand.h"
#include "model/commands/SetTimelineCommand.h"
#include "preferences/Theme.h"
#include "timeline/Playback.h"
#include "timeline/TimelineView.h"

namespace rigmesh::widgets {

namespace {

const char* const kTransportIcon = "transportIcon";

// A transport button; its icon is the style's `icon`, tinted
// (refreshTransportIcons).
QToolButton* toolButton(QWidget* parent, QStyle::StandardPixmap icon, const QString& tip) {
    auto* button = new QToolButton(parent);
    button->setProperty(kTransportIcon, static_cast<int>(icon));
    button->setToolTip(tip);
    button->setAutoRaise(true);
    return button;
}

}  // namespace

TimelineDock::TimelineDock(QWidget* parent)
    : QWidget(parent), view_(new TimelineView(this)), playback_(new Playback(this)) {
    setObjectName(QStringLiteral("timelineDock"));
    buildControls();
    refreshTransportIcons();
    connect(view_, &TimelineView::deleteRequested, this, &TimelineDock::deleteSelectedKeys);
    connect(view_, &TimelineView::copyRequested, this, &TimelineDock::copySelectedKeys);
    connect(view_, &TimelineView::pasteRequested, this, &TimelineDock::pasteKeys);
    connect(view_, &TimelineView::statusMessage, this, &TimelineDock::statusMessage);
    connect(playback_, &Playback::playingChanged, this, [this](bool playing) {
        playButton_->setProperty(kTransportIcon, static_cast<int>(playing ? QStyle::SP_MediaPause
                                                                          : QStyle::SP_MediaPlay));
        refreshTransportIcons();
    });
    setDocument(nullptr);
}

TimelineDock::~TimelineDock() {
    view_->setModel(nullptr);
}

void TimelineDock::changeEvent(QEvent* event) {
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::StyleChange)
        refreshTransportIcons();
}

void TimelineDock::refreshTransportIcons() {
    const QColor colour = palette().color(QPalette::ButtonText);
    for (QToolButton* button : findChildren<QToolButton*>()) {
        const QVariant icon = button->property(kTransportIcon);
        if (icon.isValid())
            button->setIcon(tintedIcon(
                style()->standardIcon(static_cast<QStyle::StandardPixmap>(icon.toInt())), colour));
    }
}

void TimelineDock::buildControls() {
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 2);
    bar->setSpacing(4);
    auto* toStart =
        toolButton(this, QStyle::SP_MediaSkipBackward, tr("Jump to start (Shift+Left)"));
    auto* back = toolButton(this, QStyle::SP_MediaSeekBackward, tr("Previous frame (Left)"));
    playButton_ = toolButton(this, QStyle::SP_MediaPlay, tr("Play / pause (Space)"));
    playButton_->setObjectName(QStringLiteral("timelinePlay"));
    auto* forward = toolButton(this, QStyle::SP_MediaSeekForward, tr("Next frame (Right)"));
    auto* toEnd = toolButton(this, QStyle::SP_MediaSkipForward, tr("Jump to end (Shift+Right)"));
    connect(toStart, &QToolButton::clicked, this, &TimelineDock::jumpToStart);
    connect(back, &QToolButton::clicked, this, [this] { stepFrames(-1); });
    connect(playButton_, &QToolButton::clicked, this, &TimelineDock::togglePlayback);
    connect(forward, &QToolButton::clicked, this, [this] { stepFrames(1); });
    connect(toEnd, &QToolButton::clicked, this, &TimelineDock::jumpToEnd);
    for (QWidget* w : {static_cast<QWidget*>(toStart), static_cast<QWidget*>(back),
                       static_cast<QWidget*>(playButton_), static_cast<QWidget*>(forward),
                       static_cast<QWidget*>(toEnd)})
        bar->addWidget(w);

    auto spin = [&](const QString& label, const QString& tip, int maximum) {
        auto* box = new QSpinBox(this);
        box->setRange(0, maximum);
        box->setToolTip(tip);
        box->setKeyboardTracking(false);
        if (!label.isEmpty())
            bar->addWidget(new QLabel(label, this));
        bar->addWidget(box);
        return box;
    };
    frame_ = spin(QString(), tr("Current frame"), model::kMaxFrame);
    frame_->setObjectName(QStringLiteral("timelineFrame"));
    connect(frame_, &QSpinBox::valueChanged, this, [this](int frame) {
        if (document_ && frame != document_->currentFrame())
            document_->setCurrentFrame(frame);
    });
    bar->addSpacing(8);
    start_ = spin(tr("Start"), tr("First frame of the range"), model::kMaxFrame);
    end_ = spin(tr("End"), tr("Last frame of the range"), model::kMaxFrame);
    rate_ = new QDoubleSpinBox(this);
    rate_->setRange(model::kMinFrameRate, model::kMaxFrameRate);
    rate_->setDecimals(3);
    rate_->setSuffix(tr(" fps"));
    rate_->setKeyboardTracking(false);
    rate_->setToolTip(tr("Frame rate: keys stay on their frames when it changes"));
    bar->addWidget(rate_);
    for (QAbstractSpinBox* box :
         {static_cast<QAbstractSpinBox*>(start_), static_cast<QAbstractSpinBox*>(end_),
          static_cast<QAbstractSpinBox*>(rate_)})
        connect(box, &QAbstractSpinBox::editingFinished, this, &TimelineDock::applyTimeline);

    bar->addSpacing(8);
    clipLabel_ = new QLabel(tr("Clip"), this);
    bar->addWidget(clipLabel_);
    clip_ = new QComboBox(this);
    clip_->setObjectName(QStringLiteral("timelineClip"));
    clip_->setMinimumContentsLength(8);
    clip_->setToolTip(tr("The clip the part keys and plays"));
    connect(clip_, &QComboBox::activated, this,
            [this](int index) { activateClip(clip_->itemText(index)); });
    bar->addWidget(clip_);
    clipMenu_ = new QToolButton(this);
    clipMenu_->setText(QStringLiteral("…"));
    clipMenu_->setToolTip(tr("New, duplicate, rename or delete clips"));
    clipMenu_->setPopupMode(QToolButton::InstantPopup);
    auto* menu = new QMenu(clipMenu_);
    auto ask = [this](const QString& title, const QString& initial, auto then) {
        bool ok = false;
        const QString name =
            QInputDialog::getText(this, title, tr("Clip name:"), QLineEdit::Normal, initial, &ok);
        if (ok)
            (this->*then)(name.trimmed());
    };
    menu->addAction(tr("&New Clip..."), this,
                    [this, ask] { ask(tr("New Clip"), tr("walk"), &TimelineDock::newClip); });
    menu->addAction(tr("&Duplicate Clip..."), this, [this, ask] {
        ask(tr("Duplicate Clip"), clip_->currentText() + QStringLiteral(".001"),
            &TimelineDock::duplicateClip);
    });
    menu->addAction(tr("&Rename Clip..."), this, [this, ask] {
        ask(tr("Rename Clip"), clip_->currentText(), &TimelineDock::renameClip);
    });
    menu->addAction(tr("D&elete Clip"), this, &TimelineDock::deleteClip);
    clipMenu_->setMenu(menu);
    bar->addWidget(clipMenu_);

    interpolation_ = new QComboBox(this);
    interpolation_->setToolTip(tr("Interpolation between keys"));
    interpolation_->addItem(tr("Constant"), int(rigmesh::Interpolation::Constant));
    interpolation_->addItem(tr("Linear"), int(rigmesh::Interpolation::Linear));
    interpolation_->addItem(tr("Smooth"), int(rigmesh::Interpolation::Smooth));
    playbackMode_ = new QComboBox(this);
    playbackMode_->setToolTip(tr("Before the first and after the last key"));
    playbackMode_->addItem(tr("Hold"), int(rigmesh::PlaybackMode::Hold));
    playbackMode_->addItem(tr("Loop"), int(rigmesh::PlaybackMode::Loop));
    playbackMode_->addItem(tr("Ping-Pong"), int(rigmesh::PlaybackMode::PingPong));
    for (QComboBox* box : {interpolation_, playbackMode_}) {
        connect(box, &QComboBox::activated, this, &TimelineDock::applyClipSettings);
        bar->addWidget(box);
    }

    bar->addStretch(1);
    autoKey_ = new QToolButton(this);
    autoKey_->setObjectName(QStringLiteral("timelineAutoKey"));
    autoKey_->setText(tr("● Auto Key"));
    autoKey_->setCheckable(true);
    autoKey_->setToolTip(tr("Key every pose change at the current frame"));
    autoKey_->setStyleSheet(QStringLiteral("QToolButton:checked { color: #ff4040; }"));
    connect(autoKey_, &QToolButton::toggled, this, [this](bool on) {
        if (document_)
            document_->setAutoKey(on);
    });
    onion_ = new QToolButton(this);
    onion_->setObjectName(QStringLiteral("timelineOnion"));
    onion_->setText(tr("Onion Skin"));
    onion_->setCheckable(true);
    onion_->setToolTip(tr("Show the previous and next keyed poses as ghosts"));
    connect(onion_, &QToolButton::toggled, this, &TimelineDock::onionSkinToggled);
    bar->addWidget(autoKey_);
    bar->addWidget(onion_);

    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    layout->addLayout(bar);
    layout->addWidget(view_, 1);
}

bool TimelineDock::onionSkin() const {
    return onion_->isChecked();
}

void TimelineDock::setDocument(model::Document* document) {
    playback_->setDocument(document);
    if (document_)
        disconnect(document_, nullptr, this, nullptr);
    view_->setModel(nullptr);
    model_.reset();
    document_ = document;
    if (document_) {
        model_ = std::make_unique<model::TimelineItemModel>(document_);
        view_->setModel(model_.get());
        connect(document_, &model::Document::currentFrameChanged, this, &TimelineDock::refresh);
        connect(document_, &model::Document::timelineChanged, this, &TimelineDock::refresh);
        connect(document_, &model::Document::selectionChanged, this,
                &TimelineDock::refreshClipControls);
        connect(document_, &model::Document::partChanged, this,
                [this](model::PartId, model::Document::Changes what) {
                    if (what & (model::Document::Change::Clip | model::Document::Change::Name))
                        refreshClipControls();
                });
        connect(document_, &model::Document::partInserted, this,
                &TimelineDock::refreshClipControls);
        connect(document_, &model::Document::partRemoved, this, &TimelineDock::refreshClipControls);
        connect(document_, &model::Document::autoKeyChanged, autoKey_, &QToolButton::setChecked);
    }
    for (QWidget* w : findChildren<QWidget*>())
        if (w != view_)
            w->setEnabled(document_ != nullptr);
    refresh();
}

void TimelineDock::refresh() {
    if (!document_)
        return;
    const QSignalBlocker b1(frame_), b2(start_), b3(end_), b4(rate_), b5(autoKey_);
    const model::TimelineSettings& timeline = document_->timeline();
    frame_->setValue(document_->currentFrame());
    start_->setValue(timeline.startFrame);
    end_->setValue(timeline.endFrame);
    rate_->setValue(timeline.framesPerSecond);
    autoKey_->setChecked(document_->autoKey());
    refreshClipControls();
}

model::PartId TimelineDock::clipPart() const {
    if (!document_)
        return model::kNoPart;
    if (document_->contains(document_->selection().part))
        return document_->selection().part;
    return document_->parts().empty() ? model::kNoPart : document_->parts().front().id;
}

void TimelineDock::refreshClipControls() {
    const model::PartId part = clipPart();
    const QSignalBlocker b1(clip_), b2(interpolation_), b3(playbackMode_);
    clip_->clear();
    const bool any = part != model::kNoPart;
    for (QWidget* w : {static_cast<QWidget*>(clip_), static_cast<QWidget*>(clipMenu_),
                       static_cast<QWidget*>(interpolation_), static_cast<QWidget*>(playbackMode_)})
        w->setEnabled(any);
    if (!any) {
        clipLabel_->setText(tr("Clip"));
        return;
    }
    const model::PartNode& node = document_->part(part);
    clipLabel_->setText(tr("Clip of %1").arg(node.name));
    for (const rigmesh::Clip* clip : model::clipsOf(node))
        clip_->addItem(QString::fromStdString(model::clipName(*clip)));
    clip_->setCurrentText(QString::fromStdString(model::clipName(node.clip)));
    interpolation_->setCurrentIndex(interpolation_->findData(int(node.clip.interpolation)));
    playbackMode_->setCurrentIndex(playbackMode_->findData(int(node.clip.mode)));
}

template <typename Make>
void TimelineDock::run(const QString& failure, Make make) {
    if (!document_)
        return;
    runUserAction(
        {},
        [&](const QString& text) {
            emit statusMessage(failure.arg(text), 8000);
            refresh();
        },
        [&] {
            auto command = make();
            const QString text = command->text();
            model::pushCommand(*document_, std::move(command));
            emit statusMessage(text, 4000);
        });
}

void TimelineDock::applyTimeline() {
    if (!document_)
        return;
    model::TimelineSettings settings = document_->timeline();
    settings.startFrame = start_->value();
    settings.endFrame = end_->value();
    settings.framesPerSecond = rate_->value();
    if (settings == document_->timeline())
        return;
    run(tr("Frame range not set: %1"),
        [&] { return std::make_unique<model::SetTimelineCommand>(*document_, settings); });
}

void TimelineDock::applyClipSettings() {
    const model::PartId part = clipPart();
    if (part == model::kNoPart)
        return;
    const rigmesh::Clip& clip = document_->part(part).clip;
    run(tr("Clip not changed: %1"), [&] {
        return std::make_unique<model::SetClipSettingsCommand>(
            *document_, part, clip.framesPerSecond(),
            static_cast<rigmesh::Interpolation>(interpolation_->currentData().toInt()),
            static_cast<rigmesh::PlaybackMode>(playbackMode_->currentData().toInt()));
    });
}

void TimelineDock::newClip(const QString& name) {
    run(tr("No new clip: %1"),
        [&] { return model::ClipListCommand::create(*document_, clipPart(), name.toStdString()); });
}

void TimelineDock::duplicateClip(const QString& name) {
    const model::PartId part = clipPart();
    run(tr("Not duplicated: %1"), [&] {
        return model::ClipListCommand::duplicate(
            *document_, part, model::clipName(document_->part(part).clip), name.toStdString());
    });
}

void TimelineDock::renameClip(const QString& name) {
    const model::PartId part = clipPart();
    run(tr("Not renamed: %1"), [&] {
        return model::ClipListCommand::rename(
            *document_, part, model::clipName(document_->part(part).clip), name.toStdString());
    });
}

void TimelineDock::deleteClip() {
    const model::PartId part = clipPart();
    run(tr("Not deleted: %1"), [&] {
        return model::ClipListCommand::remove(*document_, part,
                                              model::clipName(document_->part(part).clip));
    });
}

void TimelineDock::activateClip(const QString& name) {
    const model::PartId part = clipPart();
    if (part == model::kNoPart || model::clipName(document_->part(part).clip) == name.toStdString())
        return;
    run(tr("Clip not chosen: %1"),
        [&] { return model::ClipListCommand::activate(*document_, part, name.toStdString()); });
    view_->setSelectedKeys({});
    // Show the new clip's pose at this frame.
    document_->setCurrentFrame(document_->currentFrame());
}

void TimelineDock::togglePlayback() {
    playback_->toggle();
}

void TimelineDock::stepFrames(int delta) {
    if (!document_)
        return;
    playback_->pause();
    document_->setCurrentFrame(std::clamp(document_->currentFrame() + delta, 0, model::kMaxFrame));
}

void TimelineDock::jumpToStart() {
    if (!document_)
        return;
    playback_->pause();
    document_->setCurrentFrame(document_->timeline().startFrame);
}

void TimelineDock::jumpToEnd() {
    if (!document_)
        return;
    playback_->pause();
    document_->setCurrentFrame(document_->timeline().endFrame);
}

void TimelineDock::insertKey() {
    if (!document_)
        return;
    const model::PartId part = document_->contains(document_->selection().part)
                                   ? document_->selection().part
                                   : model::kNoPart;
    runUserAction(
        {},
        [this](const QString& failure) {
            emit statusMessage(tr("Not keyed: %1").arg(failure), 8000);
        },
        [&] {
            const int keyed = model::insertKeys(*document_, part);
            emit statusMessage(keyed == 0 ? tr("Nothing to key: no part has a skeleton")
                                          : tr("Keyed %n part(s) at frame %1", nullptr, keyed)
                                                .arg(document_->currentFrame()),
                               4000);
        });
}

void TimelineDock::deleteSelectedKeys() {
    if (!document_)
        return;
    runUserAction(
        tr("Delete Keys"), [this](const QString& failure) { emit statusMessage(failure, 8000); },
        [&] {
            const int deleted = model::deleteKeys(*document_, view_->selectedKeys());
            view_->setSelectedKeys({});
            emit statusMessage(deleted == 0 ? tr("Select keys to delete")
                                            : tr("Deleted %n key(s)", nullptr, deleted),
                               4000);
            if (deleted > 0)
                document_->setCurrentFrame(document_->currentFrame());
        });
}

void TimelineDock::copySelectedKeys() {
    if (!document_)
        return;
    model::KeyClipboard copied = model::copyKeys(*document_, view_->selectedKeys());
    if (copied.empty()) {
        emit statusMessage(tr("Select keys to copy"), 4000);
        return;
    }
    int count = 0;
    for (const auto& [part, keys] : copied.keys)
        count += static_cast<int>(keys.size());
    clipboard_ = std::move(copied);
    emit statusMessage(tr("Copied %n key(s)", nullptr, count), 4000);
}

void TimelineDock::pasteKeys() {
    if (!document_)
        return;
    if (clipboard_.empty()) {
        emit statusMessage(tr("Copy keys first (Ctrl+C in the timeline)"), 4000);
        return;
    }
    runUserAction(
        {},
        [this](const QString& failure) {
            emit statusMessage(tr("Not pasted: %1").arg(failure), 8000);
        },
        [&] {
            model::KeySelection pasted = model::pasteKeys(*document_, clipboard_, clipPart());
            if (pasted.empty()) {
                emit statusMessage(tr("Nothing pasted: the copied parts are gone"), 4000);
                return;
            }
            view_->setSelectedKeys(std::move(pasted));
            document_->setCurrentFrame(document_->currentFrame());
            emit statusMessage(tr("Pasted at frame %1").arg(document_->currentFrame()), 4000);
        });
}

}  // namespace rigmesh::widgets
