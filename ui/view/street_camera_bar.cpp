// SPDX-License-Identifier: MIT
#include "street_camera_bar.h"

#include "ball_view.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QLabel>
#include <QToolButton>

namespace ab::ui {

namespace {

constexpr StreetShot shots[3] = {StreetShot::Foot, StreetShot::Side, StreetShot::Flood};

} // namespace

StreetCameraBar::StreetCameraBar(BallView* view, QWidget* parent) : QWidget(parent), view_(view)
{
    setObjectName("streetCameraBar");
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    auto* label = new QLabel;
    label->setObjectName("streetCameraLabel");
    row->addWidget(label);
    const char* names[3] = {"streetFootShot", "streetSideShot", "streetFloodShot"};
    for (int i = 0; i < 3; ++i) {
        buttons_[i] = new QToolButton;
        buttons_[i]->setObjectName(names[i]);
        buttons_[i]->setCheckable(true);
        buttons_[i]->setToolButtonStyle(Qt::ToolButtonTextOnly);
        row->addWidget(buttons_[i]);
        connect(buttons_[i], &QToolButton::clicked, this, [this, i] {
            view_->setStreetShot(shots[i]);
            showShot(); // a click on the shot in use keeps it down
        });
    }
    row->addStretch(1);
    connect(view_, &BallView::streetShotChanged, this, &StreetCameraBar::showShot);
    retranslate();
    showShot();
}

void StreetCameraBar::retranslate()
{
    findChild<QLabel*>("streetCameraLabel")->setText(tr("Camera:"));
    // Short words: the bar must read whole over the view's column in lecture mode at 1280 px.
    buttons_[0]->setText(tr("Foot"));
    buttons_[0]->setToolTip(tr("Low on the road past the foot, looking up the street: the advert's shot (F)"));
    buttons_[1]->setText(tr("Side"));
    buttons_[1]->setToolTip(tr("The whole street from the side and above, the near houses cut away (S)"));
    buttons_[2]->setText(tr("Flood"));
    buttons_[2]->setToolTip(tr("Ahead of the front of the flood, moving down the hill with it (G)"));
}

void StreetCameraBar::showShot()
{
    const std::optional<StreetShot> shot = view_->streetShot();
    for (int i = 0; i < 3; ++i)
        buttons_[i]->setChecked(shot == shots[i]);
}

void StreetCameraBar::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

} // namespace ab::ui
