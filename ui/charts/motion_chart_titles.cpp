// SPDX-License-Identifier: MIT
// A MotionChart's lines and words for a scene (motion_chart.h): which lines each kind of chart
// draws, and its title forms, axis titles and line names.
#include "motion_chart.h"

#include "ui/i18n/core_text.h"

#include <QValueAxis>

namespace ab::ui {

namespace {

QString squared(const QString& unit)
{
    return unit == "1" ? unit : unit + QString::fromUtf8("\u00b2");
}

} // namespace

void MotionChart::chooseLines(int sceneAxes, const ChartUnits& units)
{
    const std::vector<int> axes = sceneAxes == 1 ? std::vector<int>{1} : std::vector<int>{0, 1, 2};
    switch (kind_) {
    case ChartKind::Position:
    case ChartKind::Velocity:
    case ChartKind::Difference:
    case ChartKind::Spin:
        shownAxes_ = axes;
        break;
    case ChartKind::Energy:
        shownAxes_ = {0};
        if (units.spins)
            shownAxes_.push_back(4);
        shownAxes_.push_back(1);
        if (units.spring)
            shownAxes_.push_back(3);
        if (units.streetBlocks > 0)
            shownAxes_.push_back(5);
        shownAxes_.push_back(2);
        break;
    case ChartKind::Momentum:
        shownAxes_ = {0, 1, 2};
        break;
    case ChartKind::Activity:
        shownAxes_ = {0, 1};
        break;
    case ChartKind::FootRate:
        shownAxes_.clear();
        for (std::size_t i = 0; i < footBlocks(units.streetBlocks).size(); ++i)
            shownAxes_.push_back(int(i));
        break;
    case ChartKind::Speeds:
        shownAxes_ = {0, 1, 2, 3};
        break;
    }
}

void MotionChart::nameChart(const SceneInfo& scene, int ball, const ChartUnits& units, QString* names)
{
    const QString time = coreText(scene.timeUnit);
    const QString length = coreText(scene.lengthUnit);
    const QString who = scene.ballCount == 1 ? tr("the ball") : tr("ball %1").arg(ball + 1);
    who_ = who;
    // Energy is m |v|^2: mass length^2 / time^2; momentum m v: mass length / time.
    const QString energyUnit = squared(length) + "/" + squared(time);
    const QString momentumUnit = length + "/" + time;
    switch (kind_) {
    case ChartKind::Position:
        titleForms_ = {tr("Position of %1").arg(who)};
        valueAxis_->setTitleText(tr("position (%1)").arg(length));
        break;
    case ChartKind::Velocity:
        titleForms_ = {tr("Velocity of %1").arg(who)};
        valueAxis_->setTitleText(tr("velocity (%1/%2)").arg(length, time));
        break;
    case ChartKind::Energy:
        nameEnergy(scene, units, energyUnit, names);
        break;
    case ChartKind::Momentum:
        titleForms_ =
            units.perUnitMass
                ? QStringList{tr("Total momentum per unit mass, all balls (%1)").arg(momentumUnit),
                              tr("Momentum per unit mass (%1)").arg(momentumUnit),
                              tr("p/m, all balls (%1)").arg(momentumUnit), tr("p/m (%1)").arg(momentumUnit)}
                : QStringList{tr("Total momentum, all balls (kg %1)").arg(momentumUnit),
                              tr("p, all balls (kg %1)").arg(momentumUnit), tr("p (kg %1)").arg(momentumUnit)};
        valueAxis_->setTitleText(units.perUnitMass ? tr("p/m") : tr("p"));
        break;
    case ChartKind::Activity:
        titleForms_ = {tr("Moving balls and impacts")};
        valueAxis_->setTitleText(tr("moving balls"));
        rateAxis_->setTitleText(tr("impacts per %1").arg(time));
        names[0] = tr("moving balls");
        names[1] = tr("impacts per %1").arg(time);
        break;
    case ChartKind::Difference:
        titleForms_ = {tr("Difference in position of %1").arg(who), tr("Difference, %1").arg(who)};
        valueAxis_->setTitleText(tr("difference (%1)").arg(length));
        break;
    case ChartKind::Spin:
        titleForms_ = {tr("Spin of %1").arg(who)};
        valueAxis_->setTitleText(tr("\u03c9 (rad/%1)").arg(time));
        break;
    case ChartKind::FootRate:
        titleForms_ = {tr("Balls passing the foot of each block"), tr("Balls past each foot")};
        // Net: balls that roll back up past a foot (superballs off a house front) count less,
        // and a foot the flood climbs back over reads below zero for that while.
        valueAxis_->setTitleText(tr("balls per %1, net").arg(time));
        nameFeet(names, units.streetBlocks);
        break;
    case ChartKind::Speeds:
        titleForms_ = {tr("Speeds of the balls on the street"), tr("Speeds on the street")};
        valueAxis_->setTitleText(tr("speed (%1/%2)").arg(length, time));
        names[0] = tr("10th percentile");
        names[1] = tr("median");
        names[2] = tr("90th percentile");
        names[3] = tr("fastest");
        break;
    }
}

void MotionChart::nameEnergy(const SceneInfo& scene, const ChartUnits& units, const QString& energyUnit, QString* names)
{
    // Of several balls the chart draws the sum, and says so: "energy per unit mass, all balls"
    // let a reader take the street's sum for one ball's (a speed of 1,900 m/s). The street's
    // 10,000 balls sum to millions of m^2/s^2, an axis of "8000000" a lecture hall cannot
    // read: its chart draws the mean a ball (ChartUnits::energyMeanOver), as its status bar.
    const bool one = scene.ballCount == 1;
    if (units.energyMeanOver > 0 && units.perUnitMass) {
        titleForms_ = {tr("Energy per unit mass, mean per ball (%1)").arg(energyUnit),
                       tr("E/m, mean per ball (%1)").arg(energyUnit), tr("mean E/m (%1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("mean E/m"));
    } else if (units.energyMeanOver > 0) {
        titleForms_ = {tr("Energy, mean per ball (kg %1)").arg(energyUnit),
                       tr("E, mean per ball (kg %1)").arg(energyUnit), tr("mean E (kg %1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("mean E"));
    } else if (units.perUnitMass && one) {
        titleForms_ = {tr("Energy per unit mass (%1)").arg(energyUnit), tr("E/m (%1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("E/m"));
    } else if (units.perUnitMass) {
        titleForms_ = {tr("Energy per unit mass, sum over all balls (%1)").arg(energyUnit),
                       tr("E/m, sum over all balls (%1)").arg(energyUnit),
                       tr("\u03a3 E/m, all balls (%1)").arg(energyUnit), tr("\u03a3 E/m (%1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("\u03a3 E/m"));
    } else if (one) {
        titleForms_ = {tr("Energy (kg %1)").arg(energyUnit), tr("E (kg %1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("E"));
    } else {
        titleForms_ = {tr("Energy, sum over all balls (kg %1)").arg(energyUnit),
                       tr("E, sum over all balls (kg %1)").arg(energyUnit), tr("\u03a3 E (kg %1)").arg(energyUnit)};
        valueAxis_->setTitleText(tr("\u03a3 E"));
    }
    names[0] = units.spins ? tr("translation") : tr("kinetic");
    names[1] = tr("potential");
    names[2] = tr("total");
    names[3] = tr("spring");
    names[4] = tr("rotation");
    names[5] = tr("left at the foot");
}

void MotionChart::nameFeet(QString* names, int blocks)
{
    const std::vector<int> feet = footBlocks(blocks);
    for (std::size_t i = 0; i < feet.size(); ++i)
        names[i] = feet[i] + 1 == blocks ? tr("foot of the street") : tr("foot of block %1").arg(feet[i] + 1);
}

} // namespace ab::ui
