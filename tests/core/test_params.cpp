// SPDX-License-Identifier: MIT
// Parameter tables and the parsing every front end shares.
#include "core/params.h"
#include "core/scene.h"

#include <QtTest>

class Params : public QObject {
    Q_OBJECT

private slots:
    void everySceneHasTheContractsParameters_data()
    {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<QStringList>("keys");
        QTest::newRow("bounce1d") << "bounce1d" << QStringList{"g", "k", "h0", "v0", "max_bounces"};
        QTest::newRow("box3d") << "box3d" << QStringList{"g", "k", "box", "p0", "v0", "max_bounces"};
        QTest::newRow("two-balls") << "two-balls"
                                   << QStringList{"g", "k", "e", "r", "box", "p1", "v1", "p2", "v2", "max_events"};
        QTest::newRow("many-balls")
            << "many-balls"
            << QStringList{"n",   "r", "box", "g", "primary_loss", "secondary_loss", "max_bounces", "contact_factor",
                           "seed"};
    }

    void everySceneHasTheContractsParameters()
    {
        QFETCH(QString, scene);
        QFETCH(QStringList, keys);
        const ab::SceneInfo* info = ab::findScene(scene.toStdString());
        QVERIFY(info);
        const ab::ParamValues values = info->defaults();
        for (const QString& k : keys)
            QVERIFY2(values.indexOf(k.toStdString()).has_value(), qPrintable(k));
    }

    void everyRowIsDescribedAndItsDefaultIsInRange()
    {
        for (const ab::SceneInfo* s : ab::allScenes()) {
            QVERIFY(!s->equations.empty());
            for (const ab::ParamSpec& p : s->params) {
                const QString where = QString::fromStdString(s->key + "." + p.key);
                QVERIFY2(!p.unit.empty() && !p.equation.empty() && !p.meaning.empty() && !p.symbol.empty(),
                         qPrintable(where));
                QVERIFY2(!ab::checkValue(p, p.defaultValue), qPrintable(where));
            }
        }
    }

    void bounce1dHasOneAxisAndNoBoxOrPairParameters()
    {
        const ab::SceneInfo& s = ab::sceneInfo(ab::SceneId::Bounce1d);
        QCOMPARE(s.axes, 1);
        const auto v = s.defaults();
        for (const char* absent : {"box", "p0", "e", "n", "mu", "beta"})
            QVERIFY(!v.indexOf(absent));
        // Its ball is a point for contact; the radius only sets its spin's inertia, so it
        // belongs to the physical model alone.
        QCOMPARE(v.spec("r").models, unsigned(ab::PhysicalModel));
    }

    void parsesNumbersAndVectors()
    {
        QCOMPARE(ab::parseReal(" 0.25 ", "x"), 0.25);
        QCOMPARE(ab::parseReal("+1e3", "x"), 1000.0);
        QCOMPARE(ab::parseInteger("42", "n"), 42LL);
        QCOMPARE(ab::parseVector("2,20,2", "p0"), Eigen::Vector3d(2, 20, 2));
        QCOMPARE(ab::parseVector("-1.5, 0 ,3e1", "v0"), Eigen::Vector3d(-1.5, 0, 30));
    }

    void refusesMalformedInputNamingIt_data()
    {
        QTest::addColumn<QString>("assignment");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("not a number") << "box3d:k=abc"
                                      << "k: 'abc' is not a number";
        QTest::newRow("trailing junk") << "box3d:k=0.5x"
                                       << "not a number";
        QTest::newRow("nan") << "box3d:k=nan"
                             << "k: 'nan' is not a finite number";
        QTest::newRow("infinity") << "box3d:g=inf"
                                  << "not a finite number";
        QTest::newRow("overflow") << "box3d:g=1e999"
                                  << "too large for a double";
        QTest::newRow("above range") << "box3d:k=1.5"
                                     << "k: 1.5 is outside the allowed range [0, 1]";
        QTest::newRow("negative box") << "box3d:box=-3"
                                      << "outside the allowed range (0,";
        QTest::newRow("zero box") << "box3d:box=0"
                                  << "box: 0 is outside";
        QTest::newRow("two components") << "box3d:p0=1,2"
                                        << "p0: '1,2' is not a vector x,y,z";
        QTest::newRow("four components") << "box3d:p0=1,2,3,4"
                                         << "not a vector";
        QTest::newRow("empty component") << "box3d:v0=1,,3"
                                         << "not a vector";
        QTest::newRow("fractional count") << "bounce1d:max_bounces=2.5"
                                          << "not a whole number";
        QTest::newRow("unknown name") << "bounce1d:box=3"
                                      << "unknown parameter 'box'";
        QTest::newRow("no equals") << "bounce1d:k"
                                   << "is not NAME=VALUE";
        QTest::newRow("empty value") << "bounce1d:k="
                                     << "is not a number";
        QTest::newRow("two signs") << "bounce1d:v0=+-5"
                                   << "is not a number";
        QTest::newRow("hex") << "bounce1d:h0=0x10"
                             << "is not a number";
        QTest::newRow("newline in the name") << "bounce1d:k\n=1"
                                             << "unknown parameter 'k\\n'";
        QTest::newRow("negative component") << "box3d:p0=-1,2,3"
                                            << "(x component) is outside";
        QTest::newRow("too many balls") << "many-balls:n=100000000"
                                        << "n: 100000000 is outside";
    }

    void refusesMalformedInputNamingIt()
    {
        QFETCH(QString, assignment);
        QFETCH(QString, mentions);
        const QStringList parts = assignment.split(':');
        const ab::SceneInfo* s = ab::findScene(parts[0].toStdString());
        ab::ParamValues values = s->defaults();
        const ab::ParamValues before = values;
        try {
            values.parseAssignment(parts[1].toStdString());
            QFAIL("accepted");
        } catch (const ab::InputError& e) {
            QVERIFY2(QString(e.what()).contains(mentions), e.what());
            QVERIFY(!QString(e.what()).contains('\n')); // one line, whatever was typed
        }
        QVERIFY(values == before); // nothing half-applied
    }

    void aRefusalCarriesItsSentenceAndTheValuesAsTyped()
    {
        ab::ParamValues values = ab::sceneInfo(ab::SceneId::Box3d).defaults();
        try {
            values.parseAssignment("v0=1,2,1e9");
            QFAIL("accepted");
        } catch (const ab::InputError& e) {
            // The window translates the sentence and fills in the same values.
            QVERIFY(e.refusal());
            QCOMPARE(e.refusal()->text, ab::refusal::componentOutsideRange);
            QCOMPARE(e.refusal()->args.size(), std::size_t(4));
            QCOMPARE(e.refusal()->args[0], std::string("v0"));
            QCOMPARE(e.refusal()->args[2], std::string("z"));
            QCOMPARE(std::string(e.what()), ab::refusalMessage(*e.refusal()));
            QVERIFY(QString(e.what()).startsWith("v0: 1000000000 (z component) is outside the allowed range"));
        }
        // One pass: a value that holds a placeholder is shown as typed.
        QCOMPARE(ab::fillRefusal("%1: %2 is not a number", {"k", "'%2'"}), std::string("k: '%2' is not a number"));
        QCOMPARE(ab::fillRefusal("%1 and %3", {"a"}), std::string("a and %3"));
    }

    void formatsValuesSoTheyReadBackExactly()
    {
        for (double x : {0.1, 0.0982, 9.82 / 1000.0, 1.0 / 3.0, 2e-300, 123456789.125})
            QCOMPARE(ab::parseReal(ab::formatNumber(x), "x"), x);
        QCOMPARE(ab::formatNumber(0.6), std::string("0.6"));
    }

    void aStepReadsAsAReaderWritesIt()
    {
        // Six significant digits or fewer as they are; one over a whole number as a fraction
        // (1/60 and 1/240 are 0.016666666666666666 and 0.004166666666666667 in full); anything
        // else to six digits.
        QCOMPARE(ab::formatStep(0.01), std::string("0.01"));
        QCOMPARE(ab::formatStep(1e-5), std::string("1e-05"));
        QCOMPARE(ab::formatStep(0.25), std::string("0.25"));
        QCOMPARE(ab::formatStep(1.0 / 60.0), std::string("1/60"));
        QCOMPARE(ab::formatStep(1.0 / 240.0), std::string("1/240"));
        QCOMPARE(ab::formatStep(1.0 / 3.0), std::string("1/3"));
        QCOMPARE(ab::formatStep(0.0166667), std::string("0.0166667"));
        QCOMPARE(ab::formatStep(0.01234567891), std::string("0.0123457"));
        QCOMPARE(ab::formatStep(1.0 / 60.0 + 1e-12), std::string("0.0166667")); // not 1/60 to round-off
    }

    void printableInputIsOneShortLine()
    {
        // Controls escaped so that no terminal sequence passes; quotes left as they are.
        QCOMPARE(ab::printableInput("a\nb\x01\"c\"\x1b[31m"), std::string("a\\nb\\x01\"c\"\\x1b[31m"));
        // A C1 control (U+009B, CSI) and a byte that is not UTF-8.
        QCOMPARE(ab::printableInput("x\xC2\x9By\xFFz"), std::string("x\\u009by\\xffz"));
        // Cut after 80 characters with an ellipsis, or after as many as asked.
        QCOMPARE(ab::printableInput(std::string(100, 'x')), std::string(80, 'x') + "\xE2\x80\xA6");
        QCOMPARE(ab::printableInput(std::string(100, 'x'), 40), std::string(40, 'x') + "\xE2\x80\xA6");
        // Characters, not bytes, are counted: never cut inside a character's UTF-8 bytes.
        QCOMPARE(ab::printableInput(std::string(79, 'x') + "\xC3\xA9yz"),
                 std::string(79, 'x') + "\xC3\xA9\xE2\x80\xA6");
    }

    void startOutsideTheBoxIsRefused()
    {
        const ab::SceneInfo& s = ab::sceneInfo(ab::SceneId::Box3d);
        ab::ParamValues v = s.defaults();
        v.parseAssignment("p0=400,20,2");
        QVERIFY_THROWS_EXCEPTION(ab::InputError, s.crossCheck(v));
    }

    void enumKeysRoundTrip()
    {
        for (ab::Integrator i : ab::allIntegrators())
            QCOMPARE(ab::parseIntegrator(ab::integratorKey(i)), i);
        QCOMPARE(ab::parseModel("physical"), ab::ModelKind::Physical);
        QVERIFY(!ab::parseModel("Physical"));
        QCOMPARE(ab::parseImpactMode("step-end"), ab::ImpactMode::StepEnd);
        QCOMPARE(ab::parseBroadphase("all-pairs"), ab::Broadphase::AllPairs);
    }
};

QTEST_GUILESS_MAIN(Params)
#include "test_params.moc"
