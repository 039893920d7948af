// SPDX-License-Identifier: MIT
// The core's displayed strings (core_text.h), listed for lupdate under the context "core".
// Kept by hand: test_ui_i18n fails, naming the string, when a core table gains a string
// that is missing here.
#include "core_text.h"

#include <QtGlobal>

namespace ab::ui {

namespace {

const char* const listed[] = {
    QT_TRANSLATE_NOOP("core", "1/step^2"),
    QT_TRANSLATE_NOOP("core", "2.1.1, 2.2.1, Appendix A, Figure 2.5"),
    QT_TRANSLATE_NOOP("core", "2.1.2, Appendix C, eqs 2.4-2.11"),
    QT_TRANSLATE_NOOP("core", "2.2.1 (Zeno)"),
    QT_TRANSLATE_NOOP("core", "2.2.2 (Zeno)"),
    QT_TRANSLATE_NOOP("core", "2.2.2, Appendix B, Appendix C (propagation), Figures 2.6-2.7"),
    QT_TRANSLATE_NOOP("core", "2.3, Appendix D, eqs 2.23-2.31, Figure 3.1"),
    QT_TRANSLATE_NOOP("core", "3.1 (air resistance)"),
    QT_TRANSLATE_NOOP("core", "A ball bouncing in one dimension"),
    QT_TRANSLATE_NOOP("core",
                      "A ball falls from rest and bounces on a floor. Flight follows dv/dt = -g and dx/dt = v (eqs "
                      "2.1-2.2); an impact reverses and shrinks the velocity, v1 = -k v0 (eq 2.3). The bounces come "
                      "ever faster (Zeno behaviour), so the report stops the ball after a fixed number of bounces."),
    QT_TRANSLATE_NOOP("core", "A floor hit is p <= 0 and v <= 0 at the start of a step. That step also sets the stored "
                              "position of the contact state to 0, and when the bounce counter exceeds max_bounces the "
                              "contact state and every later state are set to zero."),
    QT_TRANSLATE_NOOP("core", "Appendix A"),
    QT_TRANSLATE_NOOP("core", "Appendix B"),
    QT_TRANSLATE_NOOP("core", "Appendix C"),
    QT_TRANSLATE_NOOP("core", "Appendix D"),
    QT_TRANSLATE_NOOP("core", "At the floor the new vertical velocity is -k v - g dt (g the magnitude; the code adds "
                              "grav dt with grav = -9.82) and the position restarts from the floor, p[new] = v[new] "
                              "dt; the contact state's stored coordinate is set to the face it hit."),
    QT_TRANSLATE_NOOP(
        "core", "Before settling on a coefficient of restitution the report considered spring equations for the "
                "bounce. The physical model offers them as `contact` 1 (y'' = -g - k_s y - c_s v below the floor) and "
                "2 (Hertz, y'' = -g + k_h d^1.5 - c_h d^0.25 v with d = -y); their damping gives the restitution k and "
                "their stiffness the contact time t_c, and a stiff spring makes the ODE stiff."),
    QT_TRANSLATE_NOOP("core", "Each ball moves with the stage-2 rules (propagation). propagation works on a copy, so "
                              "unlike stage 2 the recorded contact state keeps its unclamped coordinate."),
    QT_TRANSLATE_NOOP("core", "Event-driven, exact"),
    QT_TRANSLATE_NOOP("core", "Every contact adds one to a counter; once it exceeds max_bounces the state the step "
                              "started from and every later state are set to zero."),
    QT_TRANSLATE_NOOP("core", "Explicit Euler"),
    QT_TRANSLATE_NOOP("core", "Implicit Euler"),
    QT_TRANSLATE_NOOP("core", "Implicit midpoint"),
    QT_TRANSLATE_NOOP(
        "core", "In the published code three.js's projectOnVector changes the vector it is called on, so v1n and v1t "
                "are one object and the decomposition collapses; the product implements the report's equations."),
    QT_TRANSLATE_NOOP("core", "Many balls in a box"),
    QT_TRANSLATE_NOOP("core",
                      "Many balls start in a small cube at the centre of a 100-wide box with random velocities. The "
                      "report's WebGL model updates once per frame: walls reverse and damp the velocity, and ball "
                      "pairs closer than 2.2 r collide along their normal with a fixed tangent (eqs 2.23-2.31)."),
    QT_TRANSLATE_NOOP("core", "One ball in a box"),
    QT_TRANSLATE_NOOP("core", "One branch per step, in this order: floor y <= 0, wall x <= 0, wall x >= box, wall z <= "
                              "0, wall z >= box, else free flight. A corner hit is handled one face per step."),
    QT_TRANSLATE_NOOP("core", "One counter, shared by both balls, counts every floor and wall contact and every swap; "
                              "once it exceeds max_events both velocities are set to zero in the state the step "
                              "started from and in every later state, while positions go on being computed."),
    QT_TRANSLATE_NOOP("core", "Runge-Kutta 4"),
    QT_TRANSLATE_NOOP("core", "Symplectic Euler"),
    QT_TRANSLATE_NOOP("core", "The ball is thrown sideways inside a 300 x 300 x 300 box with one corner at the origin "
                              "and y up. Five faces are checked (no ceiling); a hit reverses the velocity along that "
                              "face's axis and shrinks it by k, while the other axes fly on (eqs 2.17-2.22)."),
    QT_TRANSLATE_NOOP("core", "The code counts time in steps (dt = 1) with gravity 0.0982 per step^2; the text's g = "
                              "9.82 is the same physics with the step read as 0.1 s."),
    QT_TRANSLATE_NOOP("core", "The code's distance uses the y difference twice and no z difference; the product uses "
                              "the Euclidean distance the code intends."),
    QT_TRANSLATE_NOOP("core", "The code's literal 49 and -48 are box/2 - r and one radius above the floor; its push of "
                              "1 unit along the normal is one radius. With the report's r = 1 they are the same."),
    QT_TRANSLATE_NOOP(
        "core", "The equations and the refactored function propagation (Appendix C) move the position with the new "
                "velocity; the older listing of Appendix B uses the old one. The product follows the equations."),
    QT_TRANSLATE_NOOP(
        "core",
        "The fixed tangent is undefined when n.z = 0. The product uses the same direction written as t = (0.3 n.z, 0.3 "
        "n.z, -0.3 (n.x + n.y)), which equals the report's up to sign (projections do not change) and tends to (0, 0, "
        "1) as n.z -> 0; when n.x + n.y = 0 too, every tz satisfies eq 2.24 and t = (1, 1, 0)/sqrt(2) is used."),
    QT_TRANSLATE_NOOP("core",
                      "The report prints it without the /2 that eq 2.6 and the code have; the /2 is used here."),
    QT_TRANSLATE_NOOP("core", "The report prints p[new] = p[old] * v[old] * dt; its code (and intent) is p[new] = "
                              "p[old] + v[old] dt, which is what runs here."),
    QT_TRANSLATE_NOOP("core", "The report prints v1n' + v2n' - v2n'; the intent (and code) is v1n' + v2n' - v2n''."),
    QT_TRANSLATE_NOOP("core", "The report's code does not use eqs 2.4-2.11 here: when the centres are closer than 2r "
                              "after a step it swaps the two velocities and multiplies them by 0.95 (e), with no test "
                              "that the balls approach, so the swap can repeat while they still overlap."),
    QT_TRANSLATE_NOOP("core", "Two balls colliding"),
    QT_TRANSLATE_NOOP("core",
                      "Two balls start at opposite sides of the box and meet head-on along z. The textbook collision "
                      "splits each velocity into a normal part along the line of centres and a tangential part: "
                      "tangential parts are kept, normal parts follow momentum conservation and restitution e (eqs "
                      "2.4-2.11). The report's own code instead swaps the two velocities and scales them by 0.95."),
    QT_TRANSLATE_NOOP("core", "Velocities are normalised before the projection and the results get swapped speeds: "
                              "ball 1 leaves with 0.95 |v2|, ball 2 with 0.95 |v1|. A zero velocity stays zero."),
    QT_TRANSLATE_NOOP("core", "Velocity Verlet"),
    QT_TRANSLATE_NOOP("core", "Zeno"),
    QT_TRANSLATE_NOOP("core", "a ball with more bounces than this, near the floor, is put to rest on it"),
    QT_TRANSLATE_NOOP("core",
                      "a floor impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)"),
    QT_TRANSLATE_NOOP(
        "core",
        "a rebound that would rise less than this ends at rest (restitution threshold), at walls and between balls"),
    QT_TRANSLATE_NOOP("core", "along the axis of the wall that was hit"),
    QT_TRANSLATE_NOOP("core",
                      "an impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)"),
    QT_TRANSLATE_NOOP("core", "and moves on"),
    QT_TRANSLATE_NOOP("core", "at the floor the velocity reverses and shrinks by k"),
    QT_TRANSLATE_NOOP("core", "ball 1 start position"),
    QT_TRANSLATE_NOOP("core", "ball 1 start velocity"),
    QT_TRANSLATE_NOOP("core", "ball 1's normal part after"),
    QT_TRANSLATE_NOOP("core", "ball 1's normal velocity after"),
    QT_TRANSLATE_NOOP("core", "ball 1's velocity after"),
    QT_TRANSLATE_NOOP("core", "ball 2 start position"),
    QT_TRANSLATE_NOOP("core", "ball 2 start velocity"),
    QT_TRANSLATE_NOOP("core", "ball 2's normal part after"),
    QT_TRANSLATE_NOOP("core", "ball 2's normal velocity after"),
    QT_TRANSLATE_NOOP("core", "ball 2's velocity after"),
    QT_TRANSLATE_NOOP("core", "ball radius"),
    QT_TRANSLATE_NOOP("core", "ball radius; contact when centres are closer than 2r"),
    QT_TRANSLATE_NOOP(
        "core",
        "ball-ball restitution along the line of centres (the report also damps the components along a wall with it)"),
    QT_TRANSLATE_NOOP("core", "ball-ball restitution; the report's code scales the swapped velocities by it"),
    QT_TRANSLATE_NOOP("core", "coefficient of restitution at floor and walls"),
    QT_TRANSLATE_NOOP("core", "coefficient of restitution at the floor: v1 = -k v0"),
    QT_TRANSLATE_NOOP("core", "duration of one spring contact (contact 1 or 2); with k it sets stiffness and damping"),
    QT_TRANSLATE_NOOP("core", "eq 2.1, 2.15"),
    QT_TRANSLATE_NOOP("core", "eq 2.12"),
    QT_TRANSLATE_NOOP("core", "eq 2.16"),
    QT_TRANSLATE_NOOP("core", "eq 2.17"),
    QT_TRANSLATE_NOOP("core", "eq 2.19"),
    QT_TRANSLATE_NOOP("core", "eq 2.3, 2.13"),
    QT_TRANSLATE_NOOP("core", "eq 2.3, Appendix D"),
    QT_TRANSLATE_NOOP("core", "eq 2.30"),
    QT_TRANSLATE_NOOP("core", "eq 2.31"),
    QT_TRANSLATE_NOOP("core", "eq 2.4 (any masses)"),
    QT_TRANSLATE_NOOP("core", "eq 2.5"),
    QT_TRANSLATE_NOOP("core", "eqs 2.18-2.22"),
    QT_TRANSLATE_NOOP("core", "eqs 2.24-2.25"),
    QT_TRANSLATE_NOOP("core", "eqs 2.28-2.31, Appendix D"),
    QT_TRANSLATE_NOOP("core", "explicit Euler step of the velocity (g signed, down negative)"),
    QT_TRANSLATE_NOOP("core", "floor contact of the physical model: 0 impulse v1 = -k v0 (eq 2.3), 1 linear "
                              "spring-dashpot, 2 Hertz spring with damping; springs take their damping from k"),
    QT_TRANSLATE_NOOP("core", "floor hit: bounce, no gravity in that step"),
    QT_TRANSLATE_NOOP("core", "floor hit: leave the floor with the new velocity"),
    QT_TRANSLATE_NOOP("core", "frame"),
    QT_TRANSLATE_NOOP("core", "free fall"),
    QT_TRANSLATE_NOOP("core", "free fall: position moves with the OLD velocity"),
    QT_TRANSLATE_NOOP("core", "free flight: gravity is the only force"),
    QT_TRANSLATE_NOOP("core", "Walton S10, rolling S2"),
    QT_TRANSLATE_NOOP("core", "Walton S9"),
    QT_TRANSLATE_NOOP("core", "I = q m r^2"),
    QT_TRANSLATE_NOOP("core", "free rotation: w constant in flight"),
    QT_TRANSLATE_NOOP("core", "rad/s"),
    QT_TRANSLATE_NOOP("core", "rad/step"),
    QT_TRANSLATE_NOOP("core", "Coulomb friction at every contact, walls, floor and between the balls: an impact's "
                              "tangential impulse is at most mu times its normal one, and a ball sliding on the floor "
                              "feels mu m g at its contact point until it rolls (0: smooth)"),
    QT_TRANSLATE_NOOP(
        "core", "Coulomb friction at floor and walls: an impact's tangential impulse is at most mu times its normal "
                "one, and a ball sliding on the floor feels mu m g at its contact point until it rolls (0: smooth)"),
    QT_TRANSLATE_NOOP("core", "tangential restitution of the contact point's sliding velocity when friction holds it: "
                              "-1 smooth (no friction at all), 0 the contact point stops, 1 it reverses (a superball)"),
    QT_TRANSLATE_NOOP("core", "moment of inertia as a fraction of m r^2: 2/5 a solid ball, 2/3 a hollow shell"),
    QT_TRANSLATE_NOOP("core", "radius of the ball: the lever arm of friction and the r of I = q m r^2 (for contact the "
                              "ball is a point, as in the report)"),
    QT_TRANSLATE_NOOP("core", "start spin about the vertical axis, up positive (right-hand rule): the only spin a ball "
                              "moving on one axis can have; the floor's contact point has no lever on it, so it stays"),
    QT_TRANSLATE_NOOP("core", "start angular velocity of the ball (x, y, z), right-hand rule"),
    QT_TRANSLATE_NOOP("core", "start angular velocity of ball 1 (x, y, z), right-hand rule"),
    QT_TRANSLATE_NOOP("core", "start angular velocity of ball 2 (x, y, z), right-hand rule"),
    QT_TRANSLATE_NOOP("core", "gravity per frame; the code subtracts 9.82/1000 from dy each frame"),
    QT_TRANSLATE_NOOP("core", "kg"),
    QT_TRANSLATE_NOOP("core", "kg/m"),
    QT_TRANSLATE_NOOP("core", "kg/s"),
    QT_TRANSLATE_NOOP("core", "kg/step"),
    QT_TRANSLATE_NOOP("core", "kg/unit"),
    QT_TRANSLATE_NOOP("core", "linear air drag on each ball, force -b v (0: none)"),
    QT_TRANSLATE_NOOP("core", "linear air drag, force -b v (0: none)"),
    QT_TRANSLATE_NOOP("core", "m"),
    QT_TRANSLATE_NOOP("core", "m/s"),
    QT_TRANSLATE_NOOP("core", "m/s^2"),
    QT_TRANSLATE_NOOP("core", "magnitude of gravity (down is -y)"),
    QT_TRANSLATE_NOOP("core", "magnitude of gravity; the report's code scales 9.82 to 0.0982 per step^2 with dt = 1"),
    QT_TRANSLATE_NOOP("core", "mass of ball 1; momentum m1 v1 + m2 v2 is conserved in every collision"),
    QT_TRANSLATE_NOOP("core", "mass of ball 2"),
    QT_TRANSLATE_NOOP("core", "mass of the ball; with drag it sets the terminal speed sqrt(m g / c)"),
    QT_TRANSLATE_NOOP("core", "momentum along the normal"),
    QT_TRANSLATE_NOOP("core", "momentum is conserved (equal masses)"),
    QT_TRANSLATE_NOOP("core", "normal along the line of centres"),
    QT_TRANSLATE_NOOP("core", "number of balls (the report's figure shows 200)"),
    QT_TRANSLATE_NOOP("core", "position changes with velocity"),
    QT_TRANSLATE_NOOP("core", "quadratic air drag on each ball, force -c |v| v (0: none)"),
    QT_TRANSLATE_NOOP("core", "quadratic air drag, force -c |v| v (0: none)"),
    QT_TRANSLATE_NOOP("core", "report 1.2"),
    QT_TRANSLATE_NOOP("core", "restitution along the normal"),
    QT_TRANSLATE_NOOP("core", "restitution of the velocity component normal to a wall or floor"),
    QT_TRANSLATE_NOOP("core", "s"),
    QT_TRANSLATE_NOOP("core", "seed of the random start positions, velocities and colours"),
    QT_TRANSLATE_NOOP("core", "side of the box, centred at the origin; centres stay within box/2 - r of the centre"),
    QT_TRANSLATE_NOOP("core", "side of the cubic box (corner at the origin)"),
    QT_TRANSLATE_NOOP("core", "smooth balls: tangential part kept"),
    QT_TRANSLATE_NOOP("core", "spring stiffness per unit mass (Hertz: per unit^1/2); 0 takes it from contact_time"),
    QT_TRANSLATE_NOOP("core", "start height of the ball above the floor"),
    QT_TRANSLATE_NOOP("core", "start position (x, y, z), y up"),
    QT_TRANSLATE_NOOP("core", "start velocity (x, y, z)"),
    QT_TRANSLATE_NOOP("core", "start vertical velocity, up positive"),
    QT_TRANSLATE_NOOP("core", "step"),
    QT_TRANSLATE_NOOP("core", "tangential parts kept"),
    QT_TRANSLATE_NOOP("core", "that axis moves with the NEW velocity"),
    QT_TRANSLATE_NOOP("core", "the remaining horizontal axis is unchanged"),
    QT_TRANSLATE_NOOP("core",
                      "the report zeroes both velocities once more than this many contacts and swaps have happened"),
    QT_TRANSLATE_NOOP("core",
                      "the report zeroes the ball once more than this many bounces have happened (against Zeno)"),
    QT_TRANSLATE_NOOP("core",
                      "the report zeroes the ball once more than this many floor and wall contacts have happened"),
    QT_TRANSLATE_NOOP("core", "the tangent"),
    QT_TRANSLATE_NOOP("core", "two balls collide when their centres are closer than c r"),
    QT_TRANSLATE_NOOP("core", "unit"),
    QT_TRANSLATE_NOOP("core", "unit/frame^2"),
    QT_TRANSLATE_NOOP("core", "unit/step"),
    QT_TRANSLATE_NOOP("core", "unit/step^2"),
    QT_TRANSLATE_NOOP("core", "v_rest = sqrt(2 g h_rest)"),
    QT_TRANSLATE_NOOP("core", "y: gravity, Euler step"),
    QT_TRANSLATE_NOOP("core", "y: moves with the new velocity (semi-implicit)"),
    QT_TRANSLATE_NOOP("core", "z of a fixed tangent with x = y = 0.3"),
    // The models' titles and summaries.
    QT_TRANSLATE_NOOP("core", "the report's own rules"),
    QT_TRANSLATE_NOOP("core", "textbook rigid balls"),
    QT_TRANSLATE_NOOP("core", "the report's own discrete rules, bounce counters and all (one scheme per stage)"),
    QT_TRANSLATE_NOOP("core", "textbook rigid-ball physics: momentum-conserving impulses, a physical rest rule"),
    // The built-in presets' names and descriptions (resources/presets/*.json).
    QT_TRANSLATE_NOOP("core", "A sliding ball starts to roll: the 5/7 rule"),
    QT_TRANSLATE_NOOP(
        "core", "A ball set down on the floor at 5 m/s without spin, on a floor with little friction (mu = 0.02). "
                "Friction at its contact point slows the ball at mu g = 0.196 m/s^2 and spins it up, until the "
                "contact point stops slipping at t* = q v0 / ((1 + q) mu g) = 7.274 s (q = 2/5, a solid ball). From "
                "then on it rolls at 5/7 of its start speed, 3.571 m/s, with r w = v, and no friction acts on it any "
                "more: the pattern on the ball turns faster until it rolls, the spin chart levels off, and the energy"
                " chart shows rotation taking its share (and sliding losing some)."),
    QT_TRANSLATE_NOOP("core", "Back-spin: a ball that bounces backwards"),
    QT_TRANSLATE_NOOP(
        "core", "A ball thrown forwards at 6 m/s from 100 m up, with back-spin: w = 6.8 rad/s about z, r w = 25.5 m/s"
                " against its motion. At the floor friction grips the contact point (mu = 0.5, beta = 0: the contact "
                "point stops), and the angular momentum about it, m r n x v + I w, is kept (S13): the ball leaves at "
                "v' = (v - q r w) / (1 + q) = -3 m/s, backwards, rolling with r w = 3 m/s. Without the spin it would "
                "have bounced on forwards at 5/7 of 6 m/s."),
    QT_TRANSLATE_NOOP("core", "A superball under a table comes back out"),
    QT_TRANSLATE_NOOP(
        "core", "Garwin's superball (1969): with k = 1 and beta = 1 an impact that sticks reverses the contact "
                "point's slip and loses no energy. Thrown under a table, the ball bounces off the floor, then off the"
                " underside of the table, and comes back out towards the thrower. The box has no table, so gravity is"
                " off and two of its walls stand in, seen from above: the wall z = 0 (at the bottom) is the floor and"
                " z = 60 (at the top) the table's underside. The ball comes in from the left at 10 m/s without spin; "
                "the floor sends it on at 3/7 of that, 4.29 m/s, spinning with r w = 2 u / (1 + q) = 14.3 m/s (S9), "
                "and the table sends it back out to the left at 6.33 m/s. The energy stays the same to round-off."),
    QT_TRANSLATE_NOOP("core", "Two balls with friction: spin passed from one ball to the other"),
    QT_TRANSLATE_NOOP(
        "core", "Ball 1 spins about the vertical at 4 rad/s and runs at 5 m/s into ball 2, which rests without spin; "
                "gravity is off, so nothing else touches them until the walls, 5.7 s later. At the contact friction "
                "grips (mu = 0.5, beta = 0): one tangential impulse acts on the two balls at their one contact point,"
                " in opposite directions, so their momentum is kept (they move apart sideways at 1.14 m/s each) and "
                "both spins change by the same amount in the same sense (S11-S12): ball 1 keeps 2.57 rad/s and ball 2"
                " starts to spin at -1.43 rad/s, like a gear driven by the first. Choose ball 2 in the charts to "
                "follow its spin."),
    QT_TRANSLATE_NOOP("core", "Stage 1 as in the report: a ball bouncing on a floor"),
    QT_TRANSLATE_NOOP(
        "core", "The report's stage 1 (section 2.2.1, Appendix A, Figure 2.5): a ball dropped from height 2000 with "
                "gravity 0.0982 per step^2, 2000 steps of dt = 1. Each bounce reverses the velocity and keeps k = 0.6 "
                "of it (eq 2.3); once more than 10 bounces have happened, the report's counter stops the ball."),
    QT_TRANSLATE_NOOP("core", "Stage 1 twice: the report's rules beside textbook physics"),
    QT_TRANSLATE_NOOP(
        "core",
        "The report's stage 1 (solid ball, full lines) beside the physical model with symplectic Euler and impacts "
        "located inside the step (ghost ball, dotted lines): the same start, the same constants, the same step of 1. "
        "The report finds each bounce only at the end of a step and stops the ball after 10 bounces; the physical "
        "model solves each impact time inside the step and lets the ball come to rest by its own rest rule. The "
        "energy chart shows where the two part, and the difference chart how far apart the two balls are (report "
        "minus physical)."),
    QT_TRANSLATE_NOOP("core", "Zeno: infinitely many bounces in a finite time (k = 0.9)"),
    QT_TRANSLATE_NOOP(
        "core",
        "Textbook physics with k = 0.9: every bounce keeps 90 % of the speed, so every flight lasts 0.9 of the one "
        "before. The flight times form a geometric series, and infinitely many bounces fit into t = t0 (1 + k) / (1 - "
        "k) = 19 t0, about 3835 steps, where t0 = 201.8 steps is the first fall from height 2000. The event-driven "
        "integrator solves every impact time exactly; the report instead stops the ball after 10 bounces."),
    QT_TRANSLATE_NOOP("core", "Stage 2 as in the report: one ball in a box"),
    QT_TRANSLATE_NOOP("core", "The report's stage 2 (section 2.2.2, Figures 2.6 and 2.7): a ball thrown from (2, 20, "
                              "2) m at (10, 0, 15) m/s inside an open-top box of side 300 m, g = 9.82 m/s^2, 6000 "
                              "steps of 0.01 s. Floor and walls reverse the velocity along their axis and keep k = 0.9 "
                              "of it (eq 2.17); after more than 50 contacts the report's counter stops the ball."),
    QT_TRANSLATE_NOOP("core", "Late impacts: a coarse step is put back on the wall"),
    QT_TRANSLATE_NOOP("core",
                      "A fast ball (240 m/s along x) and a coarse step of 0.25 s: one step covers 60 m, a fifth of the "
                      "box. Impacts are looked for only at the end of each step, as the report does: the step from x = "
                      "270 m ends at x = 330 m, 30 m beyond the wall at x = 300 m, and the impact found there puts the "
                      "ball back on the wall and turns it at t = 1.25 s, where it should have turned at t = 1.125 s. "
                      "The ball never shows beyond the wall, but every such impact comes up to a step late: at t = "
                      "1.25 s it is on the wall instead of 27 m back from it. Set impacts to located, or the "
                      "integrator to event, and the impact time is solved inside the step. Balls that pass right "
                      "through each other between two steps: see the Tunnelling preset of stage 3."),
    QT_TRANSLATE_NOOP("core", "Tunnelling: two balls pass through each other between two steps"),
    QT_TRANSLATE_NOOP("core",
                      "Two balls of radius 5 m fly head-on at 25 m/s each, gravity off, with a coarse step of 0.5 s "
                      "and impacts looked for only at the end of each step. At t = 5 s their centres are 12.5 m apart, "
                      "2.5 m short of touching; one step later they are 12.5 m apart again, each on the other's side: "
                      "they passed through each other inside the step, and no step end saw them overlap. The health "
                      "check pauses the run there. Set impacts to located and the contact at t = 5.05 s is solved "
                      "inside the step: the balls bounce back."),
    QT_TRANSLATE_NOOP("core", "Stage 4 with the 200 balls of Figure 3.1"),
    QT_TRANSLATE_NOOP("core", "The report's WebGL model with the 200 balls its Figure 3.1 shows (its code starts 150). "
                              "Everything else is as in the report: radius 1, a box 100 wide, one update per frame."),
    QT_TRANSLATE_NOOP("core", "Stage 4 as in the report: 150 balls in a box"),
    QT_TRANSLATE_NOOP(
        "core", "The report's WebGL model (section 2.3, Appendix D): 150 balls of radius 1 start in a small cube at "
                "the centre of a box 100 wide, with random velocities, and move one update per frame for 1000 frames. "
                "Walls keep 0.9 of the normal velocity; two balls closer than 2.2 r collide by eqs 2.23-2.31."),
    QT_TRANSLATE_NOOP("core", "Head-on collision: the moving ball stops"),
    QT_TRANSLATE_NOOP(
        "core",
        "Textbook physics with gravity switched off, so only the collision changes the motion. Ball 1 moves at 10 m/s "
        "along z towards ball 2, which is at rest, centre on centre; they touch at t = 9 s. The whole velocity lies "
        "along the line of centres, so with equal masses and e = 1 (eqs 2.6-2.7) ball 1 stops dead and ball 2 leaves "
        "at 10 m/s, as in Newton's cradle. Lower e and ball 1 follows at (1 - e) 5 m/s."),
    QT_TRANSLATE_NOOP("core", "Oblique collision: the balls leave at right angles"),
    QT_TRANSLATE_NOOP("core",
                      "As the head-on collision, but ball 2 sits 5 m (one radius) to the side, so at contact the line "
                      "of centres is 30 degrees off ball 1's path. Only the normal part of ball 1's velocity, 10 cos "
                      "30 = 8.66 m/s, passes to ball 2; the tangential part, 10 sin 30 = 5 m/s, stays with ball 1 (eqs "
                      "2.8-2.9). With equal masses and e = 1 the two leave at right angles, as on a billiard table."),
    QT_TRANSLATE_NOOP("core", "Stage 3 as in the report: two balls meet head-on"),
    QT_TRANSLATE_NOOP("core", "The report's stage 3 (Appendix C): two balls of radius 1 m start at opposite walls, at "
                              "(2, 20, 2) m and (2, 20, 298) m, with velocities (10, 0, 15) and (10, 0, -15) m/s, and "
                              "meet along z. Instead of eqs 2.4-2.11 the report's code swaps the two velocities and "
                              "scales them by 0.95; run the physical model beside it to see the difference."),
    QT_TRANSLATE_NOOP("core", "rad/frame"),
    QT_TRANSLATE_NOOP("core", "start spins: each component of every ball's w uniform in [-spin, spin], drawn from the "
                              "seed (0: the balls start without spin)"),
    // The refusals (core/input_error.h).
    QT_TRANSLATE_NOOP("core", "%1: %2 is not a number"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is too small for a double (below 4.9e-324); write 0 or a larger value"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is too large for a double (above 1.8e308)"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is not a finite number"),
    QT_TRANSLATE_NOOP("core", "%1: value is not a finite number"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is not a whole number"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is too large"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is beyond 2^53 - 1 = 9007199254740991, the largest whole number kept exactly"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is not a vector x,y,z of three numbers"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is not a vector x,y,z of three finite numbers"),
    QT_TRANSLATE_NOOP("core", "%1: %2 is outside the allowed range %3"),
    QT_TRANSLATE_NOOP("core", "%1: %2 (%3 component) is outside the allowed range %4"),
    QT_TRANSLATE_NOOP("core", "%1: %2 lies outside the box of side %3 m (x and z must be within [0, box])"),
    QT_TRANSLATE_NOOP("core", "box: %1 leaves no room for a ball of radius %2 (box must exceed 2 r)"),
    QT_TRANSLATE_NOOP("core", "dt: %1 must be positive"),
    QT_TRANSLATE_NOOP("core", "steps: %1 is outside [1, %2]"),
    QT_TRANSLATE_NOOP("core", "compare with %1: %2"),
    QT_TRANSLATE_NOOP("core", "compare with %1: the two runs do not start at the same time with the same balls"),
    // Stage 5, the street.
    QT_TRANSLATE_NOOP("core", "\"Originally gravity, slope and rotation were to give the balls their initial speed and "
                              "direction.\" Here the balls start almost at rest above the top block, each velocity "
                              "component at most v_max (speed, 0.5 m/s by default): gravity and slope do the rest."),
    QT_TRANSLATE_NOOP(
        "core", "\"The basic idea was that the balls would bounce down a street like the picture from Sony's advert; "
                "the simulation was done in a simplified environment, a box, to establish that the basic functions "
                "work.\" The report's rules have no slope, kerb or crossing: this stage is the physical model's."),
    QT_TRANSLATE_NOOP("core", "3.1, Figure 1"),
    QT_TRANSLATE_NOOP("core", "Balls down a steep street"),
    QT_TRANSLATE_NOOP("core", "St1"),
    QT_TRANSLATE_NOOP("core", "St1-St2"),
    QT_TRANSLATE_NOOP("core", "St4"),
    QT_TRANSLATE_NOOP(
        "core", "The report's basic idea: balls bouncing down a steep street, as in Sony's advert, set going by "
                "gravity, slope and rotation. A hopper above the top releases them; they roll, slide and jump down the "
                "blocks, over the flat crossings, between kerbs and house fronts, and leave at the foot. The report "
                "built the box to test its functions and never reached the street, so only the physical model has it."),
    QT_TRANSLATE_NOOP("core", "a ball rolling without slipping down a block"),
    QT_TRANSLATE_NOOP("core", "a ball sliding down a block, its spin growing"),
    QT_TRANSLATE_NOOP("core", "a ball that leaves a crossing's edge flies as a projectile"),
    QT_TRANSLATE_NOOP("core",
                      "an impact whose rebound would rise less than this ends in contact: the ball rolls or slides on"),
    QT_TRANSLATE_NOOP("core", "ball radius (a superball: 3 cm)"),
    QT_TRANSLATE_NOOP("core", "cars: %1 do not fit along these blocks; they hold at most %2"),
    QT_TRANSLATE_NOOP("core", "cars: a roadway of %1 m is too narrow for parked cars"),
    QT_TRANSLATE_NOOP("core", "deg"),
    QT_TRANSLATE_NOOP("core", "eq 2.3, St5"),
    QT_TRANSLATE_NOOP("core", "every impact, with the street or a ball"),
    QT_TRANSLATE_NOOP("core", "friction holds a ball set down on a block: it rolls (St1)"),
    QT_TRANSLATE_NOOP("core", "height of the kerbs: the sidewalks stand this far above the road"),
    QT_TRANSLATE_NOOP("core", "it lands when its centre is r from the road's plane: the earliest root"),
    QT_TRANSLATE_NOOP("core", "length of a block along the road"),
    QT_TRANSLATE_NOOP("core",
                      "length of each flat crossing (the top one too); the flood leaves its lower edge as projectiles"),
    QT_TRANSLATE_NOOP("core", "number of balls released from the hopper above the top"),
    QT_TRANSLATE_NOOP("core", "parked cars (boxes) along the kerbs, spread over the blocks"),
    QT_TRANSLATE_NOOP("core", "restitution of every impact, with the street and between balls (a superball: 0.8-0.9)"),
    QT_TRANSLATE_NOOP("core", "road blocks, with a flat crossing between two"),
    QT_TRANSLATE_NOOP("core", "roadway between the kerbs"),
    QT_TRANSLATE_NOOP("core", "seed of the start positions and velocities"),
    QT_TRANSLATE_NOOP("core", "slope of every block (17 deg: a 31 % grade, San Francisco's steepest)"),
    QT_TRANSLATE_NOOP("core",
                      "start velocities: each component uniform in [-speed, speed] (gravity and slope do the rest)"),
    QT_TRANSLATE_NOOP("core", "width of each sidewalk, between kerb and house fronts"),
    QT_TRANSLATE_NOOP("core", "width: %1 m leaves no room for balls of radius %2 m (width must be at least 8 r)"),
    // The street's built-in presets.
    QT_TRANSLATE_NOOP(
        "core", "10,000 superballs with restitution 0.95 and tangential restitution 0.9 (Garwin's superball: the "
                "contact point's slip reverses at each impact, so spin turns into speed and back). They keep bouncing "
                "high all the way down, jump far off each crossing, and hit the house fronts; the energy chart shows "
                "translation and rotation trading while the total falls only slowly as the balls drop."),
    QT_TRANSLATE_NOOP("core", "One ball rolling down one block: the 5/7 rule on a slope"),
    QT_TRANSLATE_NOOP("core",
                      "One ball set down without rebound (e = 0) on a 17 deg block, 48.7 m up the road from the "
                      "foot (the hopper's lowest site). Once it has landed, friction (mu = 0.5, more than q "
                      "tan(theta)/(1 + q) = 0.087) keeps it rolling without slipping: it accelerates at a = g "
                      "sin(theta)/(1 + q) = 5/7 x 9.82 x sin 17 deg = 2.051 m/s^2, not the 2.871 m/s^2 of a ball "
                      "sliding without friction, and r w = v all the way (eq St1). The velocity chart rises in a "
                      "straight line; after t = v/a = 6.9 s it reaches the foot at v = sqrt(2 a d) = sqrt(2 x 2.051 "
                      "x 48.7) = 14.1 m/s and leaves the street."),
    QT_TRANSLATE_NOOP(
        "core", "Sony's advert released 250,000 superballs down a San Francisco street. Here they drop from the hopper "
                "over the top of three 17 deg blocks, with restitution 0.85 and grippy "
                "rubber (mu = 0.6, beta = 0.4). Seen from the foot of the hill the flood comes down the first block "
                "within 5 s and jumps at each crossing; the speed distribution widens as the front pulls away."),
    QT_TRANSLATE_NOOP("core", "Superballs: e and beta near 1"),
    QT_TRANSLATE_NOOP("core", "Ten thousand superballs down a steep street"),
    QT_TRANSLATE_NOOP("core", "The advert: a quarter of a million superballs"),
    QT_TRANSLATE_NOOP(
        "core", "The report's basic idea (chapter 3.1): balls bouncing down a steep street like Sony's advert, set "
                "going by gravity and slope. 10,000 balls of 3 cm drop from a hopper over the top of a 17 deg street "
                "(a 31 % grade) of three 80 m blocks with flat crossings between them. They land, roll and bounce down "
                "block 1 (a rolling ball gains 5/7 g sin 17 deg = 2.05 m/s^2), jump where each crossing ends, and "
                "leave at the foot; the balls-per-second chart counts them past each block's foot."),
};

} // namespace

std::vector<std::string> coreListedStrings()
{
    return {std::begin(listed), std::end(listed)};
}

} // namespace ab::ui
