// SPDX-License-Identifier: MIT
// The window's manners (offscreen): it remembers its size, the last stage and each
// stage's setup between sessions, skips a remembered setup it no longer accepts, and
// its About box credits the report's authors with the program's version.
#include "ui/about_box.h"
#include "ui/main_window.h"
#include "ui/panels/parameter_panel.h"
#include "ui/settings/window_settings.h"
#include "ui/sim/run_controller.h"

#include <QLineEdit>
#include <QSettings>
#include <QTemporaryDir>
#include <QtTest>

using ab::SceneId;
using ab::ui::MainWindow;
using ab::ui::WindowSettings;

class UiSettings : public QObject {
    Q_OBJECT

private slots:
    void nextSessionOpensOnTheLastStageWithEachStagesSetup()
    {
        QTemporaryDir dir;
        QSettings store(dir.filePath("amazeballs.ini"), QSettings::IniFormat);
        {
            MainWindow w;
            auto* settings = new WindowSettings(w, store);
            QVERIFY(!settings->restore()); // a first start: nothing to restore
            w.resize(900, 640);
            ab::ParamValues values = w.controller().spec().params;
            values.parse("k", "0.45");
            QVERIFY(w.applyValues(values)); // stage 1
            w.showScene(SceneId::Box3d);
            values = w.controller().spec().params;
            values.parse("v0", "1,2,3");
            QVERIFY(w.applyValues(values));
            w.showScene(SceneId::TwoBalls);
            settings->save();
        }
        MainWindow w;
        auto* settings = new WindowSettings(w, store);
        QVERIFY(settings->restore());
        QVERIFY(settings->skipped().isEmpty());
        QCOMPARE(w.scene(), SceneId::TwoBalls);
        QCOMPARE(w.size(), QSize(900, 640));
        w.showScene(SceneId::Bounce1d);
        QCOMPARE(w.controller().spec().params.real("k"), 0.45);
        QCOMPARE(w.parameters()->field("k")->text(), QString("0.45"));
        w.showScene(SceneId::Box3d);
        QVERIFY(w.controller().spec().params.vector("v0") == Eigen::Vector3d(1, 2, 3));
        w.showScene(SceneId::ManyBalls); // never changed: the report's constants
        QVERIFY(w.controller().spec().params == ab::sceneInfo(SceneId::ManyBalls).defaults());
    }

    void rememberedSetupThatNoLongerReadsIsSkipped()
    {
        QTemporaryDir dir;
        QSettings store(dir.filePath("amazeballs.ini"), QSettings::IniFormat);
        store.setValue("scenes/box3d", R"({"format": "amazeballs-preset", "version": 1, "name": "box3d",
            "scene": "box3d", "model": "report", "params": {"k": 7}})");
        store.setValue("window/scene", "box3d");
        MainWindow w;
        auto* settings = new WindowSettings(w, store);
        settings->restore();
        QCOMPARE(settings->skipped().size(), qsizetype(1));
        QVERIFY2(settings->skipped().front().contains("params.k"), qPrintable(settings->skipped().front()));
        QCOMPARE(w.scene(), SceneId::Box3d); // the last stage, with the report's constants
        QCOMPARE(w.controller().spec().params.real("k"), 0.9);
    }

    void aFirstStartFitsTheScreensFreeArea()
    {
        using ab::ui::WindowSettings;
        // Room for 1400 x 900 and a title bar: that size, centred.
        QCOMPARE(WindowSettings::firstStartGeometry(QRect(0, 0, 1920, 1080)), QRect(260, 90, 1400, 900));
        // A projector's 1280 x 720: the whole width, the height less the title bar, never
        // larger than the screen (it opened at 1400 x 900, its right end off the screen).
        QCOMPARE(WindowSettings::firstStartGeometry(QRect(0, 0, 1280, 720)), QRect(0, 30, 1280, 690));
        // A panel at the top: the free area starts below it.
        QCOMPARE(WindowSettings::firstStartGeometry(QRect(0, 40, 1366, 728)), QRect(0, 70, 1366, 698));
    }

    void aboutBoxCreditsTheReportAndItsAuthors()
    {
        QCoreApplication::setApplicationVersion("9.8.7");
        const QString text = ab::ui::aboutText();
        for (const char* name : {"Sofie Lindblom", "Anton Arbring", "David Lindh", "TNM085", "2014", "9.8.7"})
            QVERIFY2(text.contains(QString::fromUtf8(name)), name);
    }
};

QTEST_MAIN(UiSettings)
#include "test_ui_settings.moc"
