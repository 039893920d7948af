// SPDX-License-Identifier: MIT
// File > Export animation...: what the clip shows and how it is made. The time range of
// the run (within the run), playback speed, size (720p, 1080p or custom), frame rate
// (24-60), format (MP4, WebM, GIF) and whether the charts go beside the 3D view; it
// shows the clip's length and frame count as they change.
#pragma once

#include "video_encoder.h"

#include <QDialog>
#include <QSize>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLayout;
class QPushButton;
class QSpinBox;

namespace ab::ui {

struct AnimationChoice {
    double from = 0.0, to = 1.0, speed = 1.0;
    QSize size{1280, 720};
    int fps = 30;
    video::VideoFormat format = video::VideoFormat::Mp4;
    bool charts = false;
};

class AnimationDialog : public QDialog {
    Q_OBJECT
public:
    // `runStart`..`runEnd`: the run's time range; `rate`: run time per second at 1x;
    // `unit`: the run's time unit ("s", "step", "frame").
    AnimationDialog(double runStart, double runEnd, double rate, const QString& unit, const AnimationChoice& initial,
                    QWidget* parent = nullptr);

    AnimationChoice choice() const;
    // The line under the fields: the clip's length and frames, or what is wrong.
    QString summary() const;

private:
    QLayout* buildSizeRow(QSize initial);                   // the presets and the custom width and height
    void buildFormatFields(const AnimationChoice& initial); // frame rate, format, charts
    void update();

    double rate_;
    QDoubleSpinBox *from_, *to_, *speed_;
    QComboBox *size_, *format_;
    QSpinBox *width_, *height_, *fps_;
    QCheckBox* charts_;
    QLabel* summary_;
    QPushButton* ok_ = nullptr;
};

} // namespace ab::ui
