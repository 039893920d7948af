// SPDX-License-Identifier: MIT
#include "animation_dialog.h"

#include "core/params.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ab::ui {

namespace {

QDoubleSpinBox* timeBox(double lo, double hi, double value, const QString& unit)
{
    auto* box = new QDoubleSpinBox;
    box->setDecimals(hi - lo < 10.0 ? 3 : 2);
    box->setRange(lo, hi);
    box->setValue(value);
    box->setSuffix(" " + unit);
    box->setSingleStep(std::max((hi - lo) / 100.0, 1e-3));
    return box;
}

} // namespace

AnimationDialog::AnimationDialog(double runStart, double runEnd, double rate, const QString& unit,
                                 const AnimationChoice& initial, QWidget* parent)
    : QDialog(parent), rate_(rate)
{
    setObjectName("animationDialog");
    setWindowTitle(tr("Export animation"));
    from_ = timeBox(runStart, runEnd, std::clamp(initial.from, runStart, runEnd), unit);
    from_->setObjectName("animationFrom");
    to_ = timeBox(runStart, runEnd, std::clamp(initial.to, runStart, runEnd), unit);
    to_->setObjectName("animationTo");
    speed_ = new QDoubleSpinBox;
    speed_->setObjectName("animationSpeed");
    speed_->setRange(0.01, 1000.0);
    speed_->setDecimals(2);
    speed_->setValue(initial.speed);
    speed_->setSuffix(tr("x"));
    speed_->setToolTip(tr("1x plays the run as the window does at 1x"));
    QLayout* size = buildSizeRow(initial.size);
    buildFormatFields(initial);
    summary_ = new QLabel;
    summary_->setObjectName("animationSummary");
    summary_->setWordWrap(true);

    auto* form = new QFormLayout;
    form->addRow(tr("From"), from_);
    form->addRow(tr("To"), to_);
    form->addRow(tr("Speed"), speed_);
    form->addRow(tr("Size"), size);
    form->addRow(tr("Frame rate"), fps_);
    form->addRow(tr("Format"), format_);
    form->addRow(QString(), charts_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel);
    ok_ = buttons->addButton(tr("Export..."), QDialogButtonBox::AcceptRole);
    ok_->setDefault(true);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    auto* layout = new QVBoxLayout(this);
    layout->addLayout(form);
    layout->addWidget(summary_);
    layout->addWidget(buttons);

    for (QDoubleSpinBox* b : {from_, to_, speed_})
        connect(b, &QDoubleSpinBox::valueChanged, this, &AnimationDialog::update);
    for (QSpinBox* b : {width_, height_, fps_})
        connect(b, &QSpinBox::valueChanged, this, &AnimationDialog::update);
    for (QComboBox* b : {size_, format_})
        connect(b, &QComboBox::currentIndexChanged, this, &AnimationDialog::update);
    connect(charts_, &QCheckBox::toggled, this, &AnimationDialog::update);
    update();
}

QLayout* AnimationDialog::buildSizeRow(QSize initial)
{
    size_ = new QComboBox;
    size_->setObjectName("animationSize");
    size_->addItem(tr("720p (1280 x 720)"), QSize(1280, 720));
    size_->addItem(tr("1080p (1920 x 1080)"), QSize(1920, 1080));
    size_->addItem(tr("Custom"), QSize());
    width_ = new QSpinBox;
    height_ = new QSpinBox;
    width_->setObjectName("animationWidth");
    height_->setObjectName("animationHeight");
    for (QSpinBox* b : {width_, height_}) {
        b->setRange(16, video::kMaxSide);
        b->setSuffix(tr(" px"));
    }
    width_->setValue(initial.width());
    height_->setValue(initial.height());
    const int preset = initial == QSize(1280, 720) ? 0 : initial == QSize(1920, 1080) ? 1 : 2;
    size_->setCurrentIndex(preset);
    auto* custom = new QHBoxLayout;
    custom->addWidget(size_);
    custom->addWidget(width_);
    custom->addWidget(new QLabel(QStringLiteral("\u00d7")));
    custom->addWidget(height_);
    return custom;
}

void AnimationDialog::buildFormatFields(const AnimationChoice& initial)
{
    fps_ = new QSpinBox;
    fps_->setObjectName("animationFps");
    fps_->setRange(24, 60);
    fps_->setValue(std::clamp(initial.fps, 24, 60));
    fps_->setSuffix(tr(" frames/s"));
    format_ = new QComboBox;
    format_->setObjectName("animationFormat");
    format_->addItem(tr("MP4 (H.264): slides, players, phones"), int(video::VideoFormat::Mp4));
    format_->addItem(tr("WebM (VP9): web pages"), int(video::VideoFormat::WebM));
    format_->addItem(tr("GIF: anywhere, larger files, 256 colours"), int(video::VideoFormat::Gif));
    format_->setCurrentIndex(format_->findData(int(initial.format)));
    charts_ = new QCheckBox(tr("With the charts beside the 3D view"));
    charts_->setObjectName("animationCharts");
    charts_->setChecked(initial.charts);
}

AnimationChoice AnimationDialog::choice() const
{
    AnimationChoice c;
    c.from = from_->value();
    c.to = to_->value();
    c.speed = speed_->value();
    const QSize preset = size_->currentData().toSize();
    c.size = preset.isValid() ? preset : QSize(width_->value(), height_->value());
    c.fps = fps_->value();
    c.format = video::VideoFormat(format_->currentData().toInt());
    c.charts = charts_->isChecked();
    return c;
}

QString AnimationDialog::summary() const
{
    return summary_->text();
}

void AnimationDialog::update()
{
    const bool custom = !size_->currentData().toSize().isValid();
    width_->setEnabled(custom);
    height_->setEnabled(custom);
    if (!custom) {
        const QSize s = size_->currentData().toSize();
        width_->setValue(s.width());
        height_->setValue(s.height());
    }
    const AnimationChoice c = choice();
    QString problem;
    try {
        video::checkFrameSize(c.format, c.size.width(), c.size.height());
    } catch (const InputError&) {
        problem = tr("H.264 needs an even width and height: %1 x %2 has an odd side")
                      .arg(c.size.width())
                      .arg(c.size.height());
    }
    if (c.charts && c.size.width() < 400)
        problem = tr("The charts need a clip 400 pixels wide or more");
    const double seconds = (c.to - c.from) / (c.speed * rate_);
    const long long frames = std::llround(seconds * c.fps);
    if (problem.isEmpty() && (c.to <= c.from || frames < 1))
        problem = tr("The clip is empty: To must come after From");
    if (problem.isEmpty())
        summary_->setText(tr("%1 s of video, %2 frames").arg(double(frames) / c.fps, 0, 'f', 1).arg(frames));
    else
        summary_->setText(problem);
    ok_->setEnabled(problem.isEmpty());
}

} // namespace ab::ui
