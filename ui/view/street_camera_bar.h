// SPDX-License-Identifier: MIT
// The street's camera shots as three buttons over the 3D view (stage 5 only): from the
// foot (the advert's shot), from the side, following the flood. The button of the shot in
// use stays down; moving the camera by hand releases it. Keys: F, S, G (View menu).
#pragma once

#include <QWidget>

class QToolButton;

namespace ab::ui {

class BallView;

class StreetCameraBar : public QWidget {
    Q_OBJECT
public:
    explicit StreetCameraBar(BallView* view, QWidget* parent = nullptr);
    QToolButton* footButton() const { return buttons_[0]; }
    QToolButton* sideButton() const { return buttons_[1]; }
    QToolButton* floodButton() const { return buttons_[2]; }

protected:
    void changeEvent(QEvent* event) override;

private:
    void retranslate();
    void showShot(); // the buttons follow the view's shot

    BallView* view_;
    QToolButton* buttons_[3];
};

} // namespace ab::ui
