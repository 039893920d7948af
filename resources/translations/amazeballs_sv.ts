<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="sv_SE">
<context>
    <name>AboutBox</name>
    <message>
        <source>&lt;h3&gt;Amazeballs %1&lt;/h3&gt;&lt;p&gt;Bouncing and colliding balls, stage by stage: a teaching tool that rebuilds the student report beside textbook physics.&lt;/p&gt;&lt;p&gt;Built on the report &lt;i&gt;Amazeballs&lt;/i&gt; (Modelling project TNM085, Linköping University, 13 March 2014) by &lt;b&gt;Sofie Lindblom&lt;/b&gt;, &lt;b&gt;Anton Arbring&lt;/b&gt; and &lt;b&gt;David Lindh&lt;/b&gt;; examiner Anna Lombardi. Its four stages, equations, constants and Figures 2.5, 2.6, 2.7 and 3.1 are reproduced here as the report gives them.&lt;/p&gt;&lt;p&gt;Licensed under the MIT licence.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Amazeballs %1&lt;/h3&gt;&lt;p&gt;Studsande och kolliderande bollar, etapp för etapp: ett undervisningsverktyg som återskapar studentrapporten sida vid sida med lärobokens fysik.&lt;/p&gt;&lt;p&gt;Bygger på rapporten &lt;i&gt;Amazeballs&lt;/i&gt; (Modelleringsprojekt TNM085, Linköpings universitet, 13 mars 2014) av &lt;b&gt;Sofie Lindblom&lt;/b&gt;, &lt;b&gt;Anton Arbring&lt;/b&gt; och &lt;b&gt;David Lindh&lt;/b&gt;; examinator Anna Lombardi. Rapportens fyra etapper, ekvationer, konstanter och figurerna 2.5, 2.6, 2.7 och 3.1 återges här så som rapporten anger dem.&lt;/p&gt;&lt;p&gt;Licensierad under MIT-licensen.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>About Amazeballs</source>
        <translation>Om Amazeballs</translation>
    </message>
</context>
<context>
    <name>HealthText</name>
    <message>
        <source>the floor</source>
        <translation>golvet</translation>
    </message>
    <message>
        <source>the %1 = %2 wall</source>
        <translation>väggen %1 = %2</translation>
    </message>
    <message>
        <source>The state became non-finite (an overflow) at t = %1</source>
        <translation>Tillståndet blev icke-ändligt (ett spill) vid t = %1</translation>
    </message>
    <message>
        <source>Ball %1 is %2 beyond %3 at t = %4: it left the box</source>
        <translation>Boll %1 är %2 bortom %3 vid t = %4: den lämnade lådan</translation>
    </message>
    <message>
        <source>The ball went %1 into the floor spring at t = %2, twice deeper than its energy allows: it fell through the floor</source>
        <translation>Bollen gick %1 in i golvfjädern vid t = %2, dubbelt så djupt som dess energi tillåter: den föll genom golvet</translation>
    </message>
    <message>
        <source>The ball reached the floor spring&apos;s backstop, %1 deep at t = %2, 1.5 times deeper than its energy allows (%3): the step is beyond the method&apos;s stability</source>
        <translation>Bollen nådde golvfjäderns stopp, %1 djupt vid t = %2, 1,5 gånger djupare än dess energi tillåter (%3): steget ligger bortom metodens stabilitet</translation>
    </message>
    <message>
        <source>The ball went %1 into the floor spring at t = %2, deeper than its energy allows (%3)</source>
        <translation>Bollen gick %1 in i golvfjädern vid t = %2, djupare än dess energi tillåter (%3)</translation>
    </message>
    <message>
        <source>Ball %1 is %2 beyond %3 at t = %4: the impact was found late</source>
        <translation>Boll %1 är %2 bortom %3 vid t = %4: stöten hittades för sent</translation>
    </message>
    <message>
        <source>The energy is %1% above its start at t = %2</source>
        <translation>Energin ligger %1 % över sitt startvärde vid t = %2</translation>
    </message>
    <message>
        <source>Balls %1 and %2 overlap by %3 at t = %4</source>
        <translation>Bollarna %1 och %2 överlappar med %3 vid t = %4</translation>
    </message>
    <message>
        <source>Balls %1 and %2 passed through each other within one step at t = %3 (closest approach %4, contact at %5)</source>
        <translation>Bollarna %1 och %2 gick igenom varandra under ett enda steg vid t = %3 (minsta avstånd %4, kontakt vid %5)</translation>
    </message>
    <message>
        <source>Balls %1 and %2 grazed within one step without colliding at t = %3 (closest approach %4)</source>
        <translation>Bollarna %1 och %2 snuddade vid varandra under ett steg utan att kollidera vid t = %3 (minsta avstånd %4)</translation>
    </message>
    <message>
        <source>The momentum changed by %1% of the pair&apos;s speeds in a contact at t = %2</source>
        <translation>Rörelsemängden ändrades med %1 % av parets farter i en kontakt vid t = %2</translation>
    </message>
    <message>
        <source>The balls still overlap after a swap at t = %1, so the swap repeats</source>
        <translation>Bollarna överlappar fortfarande efter ett byte vid t = %1, så bytet upprepas</translation>
    </message>
    <message>
        <source>Ball %1 lies on the floor with speed %2 at t = %3 but does not move</source>
        <translation>Boll %1 ligger på golvet med farten %2 vid t = %3 men rör sig inte</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: eq 2.16 moves the position with the old velocity, so explicit Euler adds g² dt²/2 a step of flight, Appendix A</source>
        <translation>rapportens egen regel: ekv. 2.16 flyttar positionen med den gamla hastigheten, så explicit Euler lägger till g² dt²/2 per steg i luften, bilaga A</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: the floor rule v&apos; = -k v - g dt adds a step of gravity to each rebound, Appendix B</source>
        <translation>rapportens egen regel: golvregeln v&apos; = -k v - g dt lägger till ett steg av tyngdkraften i varje studs, bilaga B</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: the push of one radius along the normal and the extra gravity at a side wall, Appendix D</source>
        <translation>rapportens egen regel: knuffen på en radie längs normalen och den extra tyngdkraften vid en sidovägg, bilaga D</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: a colliding ball is pushed one radius along the normal without being kept in the box, and the next frame&apos;s wall check puts it back, Appendix D</source>
        <translation>rapportens egen regel: en kolliderande boll knuffas en radie längs normalen utan att hållas kvar i lådan, och nästa bildrutas väggkontroll sätter tillbaka den, bilaga D</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: one face a step, the floor first, so a ball on the floor never meets a wall, Appendix B</source>
        <translation>rapportens egen regel: en yta per steg, golvet först, så en boll på golvet möter aldrig en vägg, bilaga B</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: the velocities are swapped with no test that the balls approach, Appendix C</source>
        <translation>rapportens egen regel: hastigheterna byts utan att pröva att bollarna närmar sig varandra, bilaga C</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: both swapped velocities are scaled by e, Appendix C</source>
        <translation>rapportens egen regel: båda de bytta hastigheterna skalas med e, bilaga C</translation>
    </message>
    <message>
        <source>the report&apos;s own rule: only balls above the floor are updated, so a ball on the floor keeps its last velocity, Appendix D</source>
        <translation>rapportens egen regel: bara bollar ovanför golvet uppdateras, så en boll på golvet behåller sin senaste hastighet, bilaga D</translation>
    </message>
    <message>
        <source>A smaller step shrinks it; the physical model avoids it.</source>
        <translation>Ett mindre steg minskar det; den fysikaliska modellen undviker det.</translation>
    </message>
    <message>
        <source>The physical model avoids it.</source>
        <translation>Den fysikaliska modellen undviker det.</translation>
    </message>
    <message>
        <source>The physical model conserves momentum.</source>
        <translation>Den fysikaliska modellen bevarar rörelsemängden.</translation>
    </message>
    <message>
        <source>The report updates once per frame; the physical model avoids it.</source>
        <translation>Rapporten uppdaterar en gång per bildruta; den fysikaliska modellen undviker det.</translation>
    </message>
    <message>
        <source>The report finds impacts only at the end of a step; a smaller step shrinks it.</source>
        <translation>Rapporten hittar stötar först i slutet av ett steg; ett mindre steg minskar felet.</translation>
    </message>
    <message>
        <source>Explicit Euler gains energy at every step on a spring (dt ω₀ = %1): choose symplectic Euler, Verlet, RK4 or implicit Euler.</source>
        <translation>Explicit Euler vinner energi i varje steg på en fjäder (dt ω₀ = %1): välj symplektisk Euler, Verlet, RK4 eller implicit Euler.</translation>
    </message>
    <message>
        <source>dt ω₀ = %1, and %2 is stable only below %3: choose a step below %4 %5, or implicit Euler.</source>
        <translation>dt ω₀ = %1, och %2 är stabil bara under %3: välj ett steg under %4 %5, eller implicit Euler.</translation>
    </message>
    <message>
        <source>Explicit Euler adds energy at every step: choose symplectic Euler, Verlet or event-driven.</source>
        <translation>Explicit Euler tillför energi i varje steg: välj symplektisk Euler, Verlet eller händelsestyrd.</translation>
    </message>
    <message>
        <source>Choose impacts located inside the step, or a smaller step.</source>
        <translation>Välj stötar lokaliserade inom steget, eller ett mindre steg.</translation>
    </message>
    <message>
        <source>Choose a smaller step.</source>
        <translation>Välj ett mindre steg.</translation>
    </message>
    <message>
        <source>The street&apos;s substeps follow its fastest ball, so a smaller step does not shorten them; this is what its contact passes left where balls press on each other, most in a pile several balls deep: fewer balls pile less deep.</source>
        <translation>Gatans delsteg följer dess snabbaste boll, så ett mindre steg gör dem inte kortare; detta är vad dess kontaktpass lämnade där bollar trycker mot varandra, mest i en hög flera bollar djup: färre bollar ger en lägre hög.</translation>
    </message>
    <message>
        <source>The report&apos;s counter stopped both balls at t = %1: after more than %2 contacts and swaps both velocities are set to zero, and the positions go on from them (Appendix C)</source>
        <translation>Rapportens räknare stoppade båda bollarna vid t = %1: efter fler än %2 kontakter och byten sätts båda hastigheterna till noll, och positionerna räknas vidare från dem (bilaga C)</translation>
    </message>
    <message>
        <source>The report&apos;s bounce limit stopped the motion at t = %1 (Appendix D)</source>
        <translation>Rapportens studsgräns stoppade rörelsen vid t = %1 (bilaga D)</translation>
    </message>
    <message>
        <source>The angular momentum of ball %1 about its contact point changed by %2% at the floor at t = %3 (friction at the contact point cannot change it)</source>
        <translation>Rörelsemängdsmomentet för boll %1 kring dess kontaktpunkt ändrades med %2% vid golvet vid t = %3 (friktion i kontaktpunkten kan inte ändra det)</translation>
    </message>
    <message>
        <source>The report&apos;s bounce limit put the ball at rest on the floor at t = %1: after more than %2 bounces its position and velocity are set to zero (Appendix A)</source>
        <translation>Rapportens studsgräns lade bollen i vila på golvet vid t = %1: efter fler än %2 studsar sätts dess position och hastighet till noll (bilaga A)</translation>
    </message>
    <message>
        <source>The report&apos;s bounce limit put the ball at rest at the origin, the box&apos;s corner, at t = %1: after more than %2 floor and wall contacts its position and velocity are set to zero (Appendix B)</source>
        <translation>Rapportens studsgräns lade bollen i vila i origo, lådans hörn, vid t = %1: efter fler än %2 golv- och väggkontakter sätts dess position och hastighet till noll (bilaga B)</translation>
    </message>
</context>
<context>
    <name>MainWindow</name>
    <message>
        <source>Space, Right, PgDn</source>
        <translation>Mellanslag, Högerpil, PgDn</translation>
    </message>
    <message>
        <source>lecture mode: the next equation, then the next stage</source>
        <translation>föreläsningsläge: nästa ekvation, sedan nästa etapp</translation>
    </message>
    <message>
        <source>Left, PgUp</source>
        <translation>Vänsterpil, PgUp</translation>
    </message>
    <message>
        <source>lecture mode: back one equation</source>
        <translation>föreläsningsläge: en ekvation tillbaka</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Spela</translation>
    </message>
    <message>
        <source>the Play button runs the stage (Space walks the equations here)</source>
        <translation>knappen Spela kör etappen (Mellanslag går igenom ekvationerna här)</translation>
    </message>
    <message>
        <source>F11</source>
        <translation>F11</translation>
    </message>
    <message>
        <source>full screen; Esc leaves it</source>
        <translation>helskärm; Esc lämnar den</translation>
    </message>
    <message>
        <source>Space</source>
        <translation>Mellanslag</translation>
    </message>
    <message>
        <source>play / pause</source>
        <translation>spela / pausa</translation>
    </message>
    <message>
        <source>Right</source>
        <translation>Högerpil</translation>
    </message>
    <message>
        <source>one step</source>
        <translation>ett steg</translation>
    </message>
    <message>
        <source>R</source>
        <translation>R</translation>
    </message>
    <message>
        <source>reset the run</source>
        <translation>återställ körningen</translation>
    </message>
    <message>
        <source>[ ]</source>
        <translation>[ ]</translation>
    </message>
    <message>
        <source>slower / faster</source>
        <translation>långsammare / snabbare</translation>
    </message>
    <message>
        <source>1 - 5</source>
        <translation>1 - 5</translation>
    </message>
    <message>
        <source>the report&apos;s four stages and the street</source>
        <translation>rapportens fyra etapper och gatan</translation>
    </message>
    <message>
        <source>the report&apos;s four stages and the street; PgUp / PgDn: previous / next</source>
        <translation>rapportens fyra etapper och gatan; PgUp / PgDn: föregående / nästa</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>export the current chart (Ctrl+Shift+E: its data as CSV)</source>
        <translation>exportera aktuellt diagram (Ctrl+Shift+E: dess data som CSV)</translation>
    </message>
    <message>
        <source>Home</source>
        <translation>Home</translation>
    </message>
    <message>
        <source>reset the 3D view; T: turntable</source>
        <translation>återställ 3D-vyn; T: snurrbord</translation>
    </message>
    <message>
        <source>F S G</source>
        <translation>F S G</translation>
    </message>
    <message>
        <source>the street&apos;s camera: from the foot, from the side, following the flood</source>
        <translation>gatans kamera: från foten, från sidan, följ floden</translation>
    </message>
    <message>
        <source>&lt;b&gt;3D view&lt;/b&gt;: left drag orbits, right or middle drag (or Shift+left) pans, the wheel zooms (on the street towards what is under the pointer, and the camera stops short of the road, the houses and the cars), a click selects a ball, a double click on empty space resets the view. After a click in the view the arrow keys move the camera as in the report&apos;s WebGL program; Esc gives them back.</source>
        <translation>&lt;b&gt;3D-vyn&lt;/b&gt;: dra med vänster knapp för att kretsa, med höger eller mittknapp (eller Shift+vänster) för att panorera, hjulet zoomar (på gatan mot det som är under pekaren, och kameran stannar en bit från vägbanan, husen och bilarna), ett klick väljer en boll, ett dubbelklick på tom yta återställer vyn. Efter ett klick i vyn flyttar piltangenterna kameran som i rapportens WebGL-program; Esc lämnar tillbaka dem.</translation>
    </message>
    <message>
        <source>Keys and mouse</source>
        <translation>Tangenter och mus</translation>
    </message>
</context>
<context>
    <name>QMainWindow</name>
    <message>
        <source>&amp;Tools</source>
        <translation>Verk&amp;tyg</translation>
    </message>
    <message>
        <source>&amp;Accuracy study...</source>
        <translation>&amp;Noggrannhetsstudie...</translation>
    </message>
    <message>
        <source>Error against run time of each integrator on the current scene</source>
        <translation>Fel mot beräkningstid för varje integrator i den aktuella etappen</translation>
    </message>
    <message>
        <source>&amp;Stability suite...</source>
        <translation>&amp;Stabilitetstester...</translation>
    </message>
    <message>
        <source>Stiff and extreme cases of both models, with a verdict for each</source>
        <translation>Styva och extrema fall för båda modellerna, med en bedömning av vart och ett</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
</context>
<context>
    <name>ReportFigures</name>
    <message>
        <source>t (%1)</source>
        <translation>t (%1)</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>height y (%1)</source>
        <translation>höjd y (%1)</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Hastighet</translation>
    </message>
    <message>
        <source>v (%1)</source>
        <translation>v (%1)</translation>
    </message>
    <message>
        <source>Velocity along %1</source>
        <translation>Hastighet i %1-led</translation>
    </message>
    <message>
        <source>v%1 (%2)</source>
        <translation>v%1 (%2)</translation>
    </message>
    <message>
        <source>start</source>
        <translation>startpunkt</translation>
    </message>
    <message>
        <source>stopped by the counter, t = %1 %2</source>
        <translation>stoppad av räknaren, t = %1 %2</translation>
    </message>
    <message>
        <source>Redrawn from the report model with the report&apos;s constants: stage %1, %2 steps of %3 %4.</source>
        <translation>Omritad från rapportmodellen med rapportens konstanter: etapp %1, %2 steg om %3 %4.</translation>
    </message>
    <message>
        <source>Figure 2.5: Velocity and position of a bouncing ball in 1D</source>
        <translation>Figur 2.5: Hastighet och position för studsboll i 1D</translation>
    </message>
    <message>
        <source>Figure 2.6: Position of the ball in 3D</source>
        <translation>Figur 2.6: Bollens position i 3D</translation>
    </message>
    <message>
        <source>Figure 2.7: The ball&apos;s velocity along x, y and z</source>
        <translation>Figur 2.7: Bollens hastighet i x-, y- respektive z-led</translation>
    </message>
    <message>
        <source>Figure 3.1: Final simulation of 200 balls</source>
        <translation>Figur 3.1: Slutlig simulering av 200 bollar</translation>
    </message>
</context>
<context>
    <name>RunDescription</name>
    <message>
        <source>Stage %1 (%2)</source>
        <translation>Etapp %1 (%2)</translation>
    </message>
    <message>
        <source>, report model (the report&apos;s own step and impact rules)</source>
        <translation>, rapportens modell (rapportens egna steg och stötregler)</translation>
    </message>
    <message>
        <source>, physical model, integrator %1, impacts %2</source>
        <translation>, fysikalisk modell, integrator %1, stötar %2</translation>
    </message>
    <message>
        <source>at the step&apos;s end</source>
        <translation>vid stegets slut</translation>
    </message>
    <message>
        <source>, dt = %1 %2</source>
        <translation>, dt = %1 %2</translation>
    </message>
    <message>
        <source>%1 = %2 (report: %3)</source>
        <translation>%1 = %2 (rapporten: %3)</translation>
    </message>
    <message>
        <source>the report&apos;s constants</source>
        <translation>rapportens konstanter</translation>
    </message>
    <message>
        <source>started from a given state</source>
        <translation>startad från ett givet tillstånd</translation>
    </message>
    <message>
        <source>dotted: %1</source>
        <translation>prickad: %1</translation>
    </message>
    <message>
        <source>dashed: closed form</source>
        <translation>streckad: sluten form</translation>
    </message>
    <message>
        <source>%1 = %2 (default: %3)</source>
        <translation>%1 = %2 (standard: %3)</translation>
    </message>
    <message>
        <source>the default constants</source>
        <translation>standardkonstanterna</translation>
    </message>
    <message>
        <source>located inside the step</source>
        <translation>lokaliserade inom steget</translation>
    </message>
</context>
<context>
    <name>SceneGeometry</name>
    <message>
        <source>y (%1)</source>
        <translation>y (%1)</translation>
    </message>
    <message>
        <source>L = %1 %2</source>
        <translation>L = %1 %2</translation>
    </message>
    <message>
        <source>foot</source>
        <translation>fot</translation>
    </message>
    <message>
        <source>top, %1 %2 above the foot</source>
        <translation>krönet, %1 %2 över foten</translation>
    </message>
</context>
<context>
    <name>SpinEquations</name>
    <message>
        <source>Spin: balls that turn (physical model)</source>
        <translation>Rotation: bollar som snurrar (fysikalisk modell)</translation>
    </message>
    <message>
        <source>the ball spins about the vertical at %1 rad/%2 for the whole run: the floor cannot change that spin</source>
        <translation>bollen snurrar kring den lodräta axeln med %1 rad/%2 under hela körningen: golvet kan inte ändra den rotationen</translation>
    </message>
    <message>
        <source>the slip of the contact point along a wall of inward normal n; u = 0: the ball rolls</source>
        <translation>kontaktpunktens glidning längs en vägg med inåtriktad normal n; u = 0: bollen rullar</translation>
    </message>
    <message>
        <source>Spin</source>
        <translation>Rotation</translation>
    </message>
    <message>
        <source>The report&apos;s model has no rotation: its balls never turn, so friction (μ, β) and the start spin act in the physical model only. Choose the physical model to see them.</source>
        <translation>Rapportens modell har ingen rotation: dess bollar snurrar aldrig, så friktionen (μ, β) och startrotationen verkar bara i den fysikaliska modellen. Välj den fysikaliska modellen för att se dem.</translation>
    </message>
    <message>
        <source>per unit mass: %1 × (%2 %3)² = %4 %3²</source>
        <translation>per massenhet: %1 × (%2 %3)² = %4 %3²</translation>
    </message>
    <message>
        <source>q = %1, r = %2 %3: I1 = %4 kg %3², I2 = %5 kg %3²</source>
        <translation>q = %1, r = %2 %3: I1 = %4 kg %3², I2 = %5 kg %3²</translation>
    </message>
    <message>
        <source>%1 × %2 kg × (%3 %4)² = %5 kg %4²</source>
        <translation>%1 × %2 kg × (%3 %4)² = %5 kg %4²</translation>
    </message>
    <message>
        <source>sliding on the floor: μ g = %1 %2/%3² slows the centre and spins the ball up</source>
        <translation>glidning på golvet: μ g = %1 %2/%3² bromsar centrum och sätter bollen i rotation</translation>
    </message>
    <message>
        <source>the time a ball sliding at slip |u| takes to roll</source>
        <translation>tiden det tar för en boll som glider med glidningen |u| att börja rulla</translation>
    </message>
    <message>
        <source>the rolling state: the angular momentum about the contact point is kept; a ball without spin rolls on at 1/(1 + q) of its speed (5/7 for a solid ball)</source>
        <translation>rullningstillståndet: rörelsemängdsmomentet kring kontaktpunkten bevaras; en boll utan rotation rullar vidare med 1/(1 + q) av sin fart (5/7 för en massiv boll)</translation>
    </message>
    <message>
        <source>this start slides for t* = %1 %2</source>
        <translation>denna start glider i t* = %1 %2</translation>
    </message>
    <message>
        <source>then it rolls at %1 %2/%3 (%4 of its start speed of %5 %2/%3), r ω = v</source>
        <translation>sedan rullar den med %1 %2/%3 (%4 av startfarten %5 %2/%3), r ω = v</translation>
    </message>
    <message>
        <source>an impact that sticks: the slip u becomes −β u = %1 u (β = %2)</source>
        <translation>en stöt som fastnar: glidningen u blir −β u = %1 u (β = %2)</translation>
    </message>
    <message>
        <source>an impact that slides: at most μ = %1 times the normal impulse (Walton: the smaller of S9 and S10)</source>
        <translation>en stöt som glider: högst μ = %1 gånger normalimpulsen (Walton: den mindre av S9 och S10)</translation>
    </message>
    <message>
        <source>between two balls: their momentum is kept and both spins change in the same sense</source>
        <translation>mellan två bollar: rörelsemängden bevaras och båda rotationerna ändras åt samma håll</translation>
    </message>
    <message>
        <source>at a wall or the floor the angular momentum about the contact point is kept</source>
        <translation>vid en vägg eller golvet bevaras rörelsemängdsmomentet kring kontaktpunkten</translation>
    </message>
    <message>
        <source>%1 = 1 and β = 1: an impact that sticks loses no energy (a superball)</source>
        <translation>%1 = 1 och β = 1: en stöt som fastnar förlorar ingen energi (en superboll)</translation>
    </message>
    <message>
        <source>smooth contacts (μ = 0 or β = −1): no impulse along a wall, so every spin stays as it started</source>
        <translation>glatta kontakter (μ = 0 eller β = −1): ingen impuls längs en vägg, så varje rotation förblir som den startade</translation>
    </message>
    <message>
        <source>an impact that sticks: the contact point stops (β = 0)</source>
        <translation>en stöt som fastnar: kontaktpunkten stannar (β = 0)</translation>
    </message>
</context>
<context>
    <name>StreetEquations</name>
    <message>
        <source>The street with these constants</source>
        <translation>Gatan med de här konstanterna</translation>
    </message>
    <message>
        <source>down a block of %1 deg: a = %2 m/s² (%3)</source>
        <translation>nedför ett kvarter på %1 grader: a = %2 m/s² (%3)</translation>
    </message>
    <message>
        <source>rolling</source>
        <translation>rullar</translation>
    </message>
    <message>
        <source>sliding</source>
        <translation>glider</translation>
    </message>
    <message>
        <source>rolling needs μ ≥ %1; here μ = %2: a ball set down on a block %3</source>
        <translation>att rulla kräver μ ≥ %1; här är μ = %2: en boll som sätts ned på ett kvarter %3</translation>
    </message>
    <message>
        <source>rolls</source>
        <translation>rullar</translation>
    </message>
    <message>
        <source>slides</source>
        <translation>glider</translation>
    </message>
    <message>
        <source>from rest at a block&apos;s top, a ball reaches its foot at %1 m/s, %2 km/h</source>
        <translation>från vila vid ett kvarters krön når en boll dess fot med %1 m/s, %2 km/h</translation>
    </message>
    <message>
        <source>leaving a crossing at that speed, a ball flies %1 s and lands %2 m down the next block</source>
        <translation>när en boll lämnar en korsning med den farten flyger den %1 s och landar %2 m nedför nästa kvarter</translation>
    </message>
    <message>
        <source>the street drops %1 m: %2 J per kg, the speed √(2 g H) = %3 m/s if none were lost</source>
        <translation>gatan faller %1 m: %2 J per kg, farten √(2 g H) = %3 m/s om inget gick förlorat</translation>
    </message>
</context>
<context>
    <name>Theme</name>
    <message>
        <source>Light</source>
        <translation>Ljust</translation>
    </message>
    <message>
        <source>Dark</source>
        <translation>Mörkt</translation>
    </message>
    <message>
        <source>High contrast light</source>
        <translation>Hög kontrast, ljust</translation>
    </message>
    <message>
        <source>High contrast dark</source>
        <translation>Hög kontrast, mörkt</translation>
    </message>
</context>
<context>
    <name>ab::ui::AnimationActions</name>
    <message>
        <source>Export animation...</source>
        <translation>Exportera animering...</translation>
    </message>
    <message>
        <source>Writing %1</source>
        <translation>Skriver %1</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Export animation</source>
        <translation>Exportera animering</translation>
    </message>
    <message>
        <source>Wrote %1: %2 frames</source>
        <translation>Skrev %1: %2 bildrutor</translation>
    </message>
    <message>
        <source>Export cancelled; no file was written</source>
        <translation>Exporten avbröts; ingen fil skrevs</translation>
    </message>
    <message>
        <source>%1 video (*.%2)</source>
        <translation>%1-video (*.%2)</translation>
    </message>
    <message>
        <source>The animation was not written: %1</source>
        <translation>Animeringen skrevs inte: %1</translation>
    </message>
</context>
<context>
    <name>ab::ui::AnimationDialog</name>
    <message>
        <source>Export animation</source>
        <translation>Exportera animering</translation>
    </message>
    <message>
        <source>x</source>
        <translation>x</translation>
    </message>
    <message>
        <source>1x plays the run as the window does at 1x</source>
        <translation>1x spelar körningen som fönstret gör vid 1x</translation>
    </message>
    <message>
        <source>720p (1280 x 720)</source>
        <translation>720p (1280 x 720)</translation>
    </message>
    <message>
        <source>1080p (1920 x 1080)</source>
        <translation>1080p (1920 x 1080)</translation>
    </message>
    <message>
        <source>Custom</source>
        <translation>Egen</translation>
    </message>
    <message>
        <source> px</source>
        <translation> px</translation>
    </message>
    <message>
        <source> frames/s</source>
        <translation> bildrutor/s</translation>
    </message>
    <message>
        <source>MP4 (H.264): slides, players, phones</source>
        <translation>MP4 (H.264): presentationer, spelare, telefoner</translation>
    </message>
    <message>
        <source>WebM (VP9): web pages</source>
        <translation>WebM (VP9): webbsidor</translation>
    </message>
    <message>
        <source>GIF: anywhere, larger files, 256 colours</source>
        <translation>GIF: överallt, större filer, 256 färger</translation>
    </message>
    <message>
        <source>With the charts beside the 3D view</source>
        <translation>Med diagrammen bredvid 3D-vyn</translation>
    </message>
    <message>
        <source>From</source>
        <translation>Från</translation>
    </message>
    <message>
        <source>To</source>
        <translation>Till</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Hastighet</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Storlek</translation>
    </message>
    <message>
        <source>Frame rate</source>
        <translation>Bildfrekvens</translation>
    </message>
    <message>
        <source>Format</source>
        <translation>Format</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Exportera...</translation>
    </message>
    <message>
        <source>H.264 needs an even width and height: %1 x %2 has an odd side</source>
        <translation>H.264 kräver jämn bredd och höjd: %1 x %2 har en udda sida</translation>
    </message>
    <message>
        <source>The charts need a clip 400 pixels wide or more</source>
        <translation>Diagrammen kräver ett klipp som är minst 400 pixlar brett</translation>
    </message>
    <message>
        <source>The clip is empty: To must come after From</source>
        <translation>Klippet är tomt: Till måste komma efter Från</translation>
    </message>
    <message>
        <source>%1 s of video, %2 frames</source>
        <translation>%1 s video, %2 bildrutor</translation>
    </message>
</context>
<context>
    <name>ab::ui::AnimationFrames</name>
    <message>
        <source>t = %1 %2</source>
        <translation>t = %1 %2</translation>
    </message>
</context>
<context>
    <name>ab::ui::BallView</name>
    <message>
        <source>3D view</source>
        <translation>3D-vy</translation>
    </message>
    <message>
        <source>OpenGL error: %1</source>
        <translation>OpenGL-fel: %1</translation>
    </message>
    <message>
        <source>Arrow keys move the camera; Esc gives the keys back to the transport</source>
        <translation>Piltangenterna flyttar kameran; Esc lämnar tillbaka tangenterna till uppspelningen</translation>
    </message>
</context>
<context>
    <name>ab::ui::ChartPanel</name>
    <message>
        <source>Charts of ball</source>
        <translation>Diagram för boll</translation>
    </message>
    <message>
        <source>The ball the charts and the trace follow (or click a ball in the 3D view)</source>
        <translation>Bollen som diagrammen och spåret följer (eller klicka på en boll i 3D-vyn)</translation>
    </message>
    <message>
        <source>Right-click a chart to export it</source>
        <translation>Högerklicka på ett diagram för att exportera det</translation>
    </message>
    <message>
        <source>of %1</source>
        <translation>av %1</translation>
    </message>
    <message>
        <source>Export this chart as PNG...</source>
        <translation>Exportera diagrammet som PNG...</translation>
    </message>
    <message>
        <source>Export this chart as SVG...</source>
        <translation>Exportera diagrammet som SVG...</translation>
    </message>
    <message>
        <source>Export the chart data as CSV...</source>
        <translation>Exportera diagrammens data som CSV...</translation>
    </message>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Hastighet</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energi</translation>
    </message>
    <message>
        <source>Momentum</source>
        <translation>Rörelsemängd</translation>
    </message>
    <message>
        <source>Activity</source>
        <translation>Aktivitet</translation>
    </message>
    <message>
        <source>Difference</source>
        <translation>Skillnad</translation>
    </message>
    <message>
        <source>Spin</source>
        <translation>Rotation</translation>
    </message>
    <message>
        <source>Foot rate</source>
        <translation>Takt vid foten</translation>
    </message>
    <message>
        <source>Speeds</source>
        <translation>Farter</translation>
    </message>
    <message>
        <source>Chart page</source>
        <translation>Diagramsida</translation>
    </message>
    <message>
        <source>The charts shown: one page of the stage&apos;s charts</source>
        <translation>Diagrammen som visas: en sida av etappens diagram</translation>
    </message>
    <message>
        <source>Export this chart as PDF...</source>
        <translation>Exportera diagrammet som PDF...</translation>
    </message>
</context>
<context>
    <name>ab::ui::ExportOptionsDialog</name>
    <message>
        <source>Figure size and contents</source>
        <translation>Figurens storlek och innehåll</translation>
    </message>
    <message>
        <source>Report column (85 mm wide)</source>
        <translation>Rapportspalt (85 mm bred)</translation>
    </message>
    <message>
        <source>Report full width (170 mm)</source>
        <translation>Rapportens hela bredd (170 mm)</translation>
    </message>
    <message>
        <source>Slide (1920 x 1080 px, 16:9)</source>
        <translation>Bildspel (1920 x 1080 px, 16:9)</translation>
    </message>
    <message>
        <source>Custom size</source>
        <translation>Egen storlek</translation>
    </message>
    <message>
        <source>For</source>
        <translation>För</translation>
    </message>
    <message>
        <source>mm</source>
        <translation>mm</translation>
    </message>
    <message>
        <source>px</source>
        <translation>px</translation>
    </message>
    <message>
        <source>Size</source>
        <translation>Storlek</translation>
    </message>
    <message>
        <source> dpi</source>
        <translation> dpi</translation>
    </message>
    <message>
        <source>Pixels per inch of the PNG: 300 for print</source>
        <translation>PNG-bildens bildpunkter per tum: 300 för tryck</translation>
    </message>
    <message>
        <source>SVG and PDF are vector images: they have no dpi</source>
        <translation>SVG och PDF är vektorbilder: de har ingen dpi</translation>
    </message>
    <message>
        <source>Resolution</source>
        <translation>Upplösning</translation>
    </message>
    <message>
        <source>Caption: scene, model, integrator, impacts, dt and changed constants</source>
        <translation>Bildtext: scen, modell, integrator, stötar, dt och ändrade konstanter</translation>
    </message>
    <message>
        <source>Draw the time cursor</source>
        <translation>Rita tidsmarkören</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportera</translation>
    </message>
    <message>
        <source>size</source>
        <translation>storlek</translation>
    </message>
    <message>
        <source>%1 x %2 mm</source>
        <translation>%1 x %2 mm</translation>
    </message>
    <message>
        <source>, %1 x %2 px at %3 dpi</source>
        <translation>, %1 x %2 px vid %3 dpi</translation>
    </message>
</context>
<context>
    <name>ab::ui::FigureActions</name>
    <message>
        <source>F&amp;igures</source>
        <translation>F&amp;igurer</translation>
    </message>
</context>
<context>
    <name>ab::ui::FigureDialog</name>
    <message>
        <source>Export PNG...</source>
        <translation>Exportera PNG...</translation>
    </message>
    <message>
        <source>Export SVG...</source>
        <translation>Exportera SVG...</translation>
    </message>
    <message>
        <source>SVG image (*.svg)</source>
        <translation>SVG-bild (*.svg)</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-bild (*.png)</translation>
    </message>
    <message>
        <source>Export figure</source>
        <translation>Exportera figur</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Exporten misslyckades</translation>
    </message>
    <message>
        <source>Export PDF...</source>
        <translation>Exportera PDF...</translation>
    </message>
    <message>
        <source>PDF document (*.pdf)</source>
        <translation>PDF-dokument (*.pdf)</translation>
    </message>
</context>
<context>
    <name>ab::ui::MainWindow</name>
    <message>
        <source>Amazeballs</source>
        <translation>Amazeballs</translation>
    </message>
    <message>
        <source>Transport</source>
        <translation>Uppspelning</translation>
    </message>
    <message>
        <source>&lt;b&gt;Run&lt;/b&gt;</source>
        <translation>&lt;b&gt;Körning&lt;/b&gt;</translation>
    </message>
    <message>
        <source>&lt;b&gt;Constants&lt;/b&gt; (hover for the equation)</source>
        <translation>&lt;b&gt;Konstanter&lt;/b&gt; (håll muspekaren över för ekvationen)</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL, which the &apos;%1&apos; platform does not offer.
Charts, constants and the run work as usual.</source>
        <translation>3D-vyn behöver OpenGL, som plattformen &apos;%1&apos; inte erbjuder.
Diagram, konstanter och körningen fungerar som vanligt.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Arkiv</translation>
    </message>
    <message>
        <source>Export current chart...</source>
        <translation>Exportera aktuellt diagram...</translation>
    </message>
    <message>
        <source>Ctrl+E</source>
        <translation>Ctrl+E</translation>
    </message>
    <message>
        <source>Export chart</source>
        <translation>Exportera diagram</translation>
    </message>
    <message>
        <source>%1 chart...</source>
        <translation>Diagrammet %1...</translation>
    </message>
    <message>
        <source>Export chart data as CSV...</source>
        <translation>Exportera diagramdata som CSV...</translation>
    </message>
    <message>
        <source>Ctrl+Shift+E</source>
        <translation>Ctrl+Shift+E</translation>
    </message>
    <message>
        <source>Export 3D view as PNG...</source>
        <translation>Exportera 3D-vyn som PNG...</translation>
    </message>
    <message>
        <source>Quit</source>
        <translation>Avsluta</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Körning</translation>
    </message>
    <message>
        <source>Play / pause</source>
        <translation>Spela / pausa</translation>
    </message>
    <message>
        <source>One step</source>
        <translation>Ett steg</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Återställ</translation>
    </message>
    <message>
        <source>Slower</source>
        <translation>Långsammare</translation>
    </message>
    <message>
        <source>Faster</source>
        <translation>Snabbare</translation>
    </message>
    <message>
        <source>&amp;Stage</source>
        <translation>&amp;Etapp</translation>
    </message>
    <message>
        <source>%1  %2</source>
        <translation>%1  %2</translation>
    </message>
    <message>
        <source>Previous stage</source>
        <translation>Föregående etapp</translation>
    </message>
    <message>
        <source>Next stage</source>
        <translation>Nästa etapp</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Visa</translation>
    </message>
    <message>
        <source>Reset view</source>
        <translation>Återställ vyn</translation>
    </message>
    <message>
        <source>Turntable</source>
        <translation>Snurrbord</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hjälp</translation>
    </message>
    <message>
        <source>Keys and mouse</source>
        <translation>Tangenter och mus</translation>
    </message>
    <message>
        <source>About Amazeballs</source>
        <translation>Om Amazeballs</translation>
    </message>
    <message>
        <source>Amazeballs - stage %1: %2</source>
        <translation>Amazeballs - etapp %1: %2</translation>
    </message>
    <message>
        <source>closed form</source>
        <translation>sluten form</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV-tabell (*.csv)</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportera</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Skrev %1</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Exporten misslyckades</translation>
    </message>
    <message>
        <source>Export 3D view</source>
        <translation>Exportera 3D-vyn</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-bild (*.png)</translation>
    </message>
    <message>
        <source>Writing %1</source>
        <translation>Skriver %1</translation>
    </message>
    <message>
        <source>Export cancelled: nothing written</source>
        <translation>Exporten avbröts: inget skrevs</translation>
    </message>
    <message>
        <source>Went back to t = %1 %2: the run goes on from there, and what came after is dropped</source>
        <translation>Tillbaka till t = %1 %2: körningen fortsätter därifrån, och det som kom efter kastas</translation>
    </message>
    <message>
        <source>solid: %1, ghost: %2</source>
        <translation>hel: %1, spöke: %2</translation>
    </message>
    <message>
        <source>SVG image (*.svg);;PDF document (*.pdf);;PNG image (*.png)</source>
        <translation>SVG-bild (*.svg);;PDF-dokument (*.pdf);;PNG-bild (*.png)</translation>
    </message>
    <message>
        <source>PNG image (*.png);;PDF document (*.pdf);;SVG image (*.svg)</source>
        <translation>PNG-bild (*.png);;PDF-dokument (*.pdf);;SVG-bild (*.svg)</translation>
    </message>
    <message>
        <source>Street: from the foot</source>
        <translation>Gatan: från foten</translation>
    </message>
    <message>
        <source>Street: from the side</source>
        <translation>Gatan: från sidan</translation>
    </message>
    <message>
        <source>Street: follow the flood</source>
        <translation>Gatan: följ floden</translation>
    </message>
    <message>
        <source>PDF document (*.pdf);;SVG image (*.svg);;PNG image (*.png)</source>
        <translation>PDF-dokument (*.pdf);;SVG-bild (*.svg);;PNG-bild (*.png)</translation>
    </message>
</context>
<context>
    <name>ab::ui::MotionChart</name>
    <message>
        <source>the ball</source>
        <translation>bollen</translation>
    </message>
    <message>
        <source>ball %1</source>
        <translation>boll %1</translation>
    </message>
    <message>
        <source>Position of %1</source>
        <translation>Position för %1</translation>
    </message>
    <message>
        <source>position (%1)</source>
        <translation>position (%1)</translation>
    </message>
    <message>
        <source>Velocity of %1</source>
        <translation>Hastighet för %1</translation>
    </message>
    <message>
        <source>velocity (%1/%2)</source>
        <translation>hastighet (%1/%2)</translation>
    </message>
    <message>
        <source>E/m</source>
        <translation>E/m</translation>
    </message>
    <message>
        <source>t (%1)</source>
        <translation>t (%1)</translation>
    </message>
    <message>
        <source>E</source>
        <translation>E</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetisk</translation>
    </message>
    <message>
        <source>potential</source>
        <translation>potentiell</translation>
    </message>
    <message>
        <source>total</source>
        <translation>summa</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>fjäder</translation>
    </message>
    <message>
        <source>Total momentum per unit mass, all balls (%1)</source>
        <translation>Total rörelsemängd per massenhet, alla bollar (%1)</translation>
    </message>
    <message>
        <source>Total momentum, all balls (kg %1)</source>
        <translation>Total rörelsemängd, alla bollar (kg %1)</translation>
    </message>
    <message>
        <source>p/m</source>
        <translation>p/m</translation>
    </message>
    <message>
        <source>p</source>
        <translation>p</translation>
    </message>
    <message>
        <source>Moving balls and impacts</source>
        <translation>Rörliga bollar och stötar</translation>
    </message>
    <message>
        <source>moving balls</source>
        <translation>rörliga bollar</translation>
    </message>
    <message>
        <source>impacts per %1</source>
        <translation>stötar per %1</translation>
    </message>
    <message>
        <source>closed form</source>
        <translation>sluten form</translation>
    </message>
    <message>
        <source>Difference in position of %1</source>
        <translation>Skillnad i läge för %1</translation>
    </message>
    <message>
        <source>difference (%1)</source>
        <translation>skillnad (%1)</translation>
    </message>
    <message>
        <source>simulation</source>
        <translation>simulering</translation>
    </message>
    <message>
        <source>(no comparison or closed form to subtract)</source>
        <translation>(ingen jämförelse eller sluten form att dra ifrån)</translation>
    </message>
    <message>
        <source>= %1 minus %2</source>
        <translation>= %1 minus %2</translation>
    </message>
    <message>
        <source>translation</source>
        <translation>translationsenergi</translation>
    </message>
    <message>
        <source>rotation</source>
        <translation>rotationsenergi</translation>
    </message>
    <message>
        <source>Spin of %1</source>
        <translation>Rotation för %1</translation>
    </message>
    <message>
        <source>ω (rad/%1)</source>
        <translation>ω (rad/%1)</translation>
    </message>
    <message>
        <source>Balls passing the foot of each block</source>
        <translation>Bollar förbi varje kvarters fot</translation>
    </message>
    <message>
        <source>Speeds of the balls on the street</source>
        <translation>Farterna hos bollarna på gatan</translation>
    </message>
    <message>
        <source>speed (%1/%2)</source>
        <translation>fart (%1/%2)</translation>
    </message>
    <message>
        <source>10th percentile</source>
        <translation>10:e percentilen</translation>
    </message>
    <message>
        <source>median</source>
        <translation>medianfart</translation>
    </message>
    <message>
        <source>90th percentile</source>
        <translation>90:e percentilen</translation>
    </message>
    <message>
        <source>fastest</source>
        <translation>snabbast</translation>
    </message>
    <message>
        <source>foot of the street</source>
        <translation>gatans fot</translation>
    </message>
    <message>
        <source>foot of block %1</source>
        <translation>kvarter %1:s fot</translation>
    </message>
    <message>
        <source>Energy per unit mass (%1)</source>
        <translation>Energi per massenhet (%1)</translation>
    </message>
    <message>
        <source>E/m (%1)</source>
        <translation>E/m (%1)</translation>
    </message>
    <message>
        <source>E (kg %1)</source>
        <translation>E (kg %1)</translation>
    </message>
    <message>
        <source>Momentum per unit mass (%1)</source>
        <translation>Rörelsemängd per massenhet (%1)</translation>
    </message>
    <message>
        <source>p/m, all balls (%1)</source>
        <translation>p/m, alla bollar (%1)</translation>
    </message>
    <message>
        <source>p/m (%1)</source>
        <translation>p/m (%1)</translation>
    </message>
    <message>
        <source>p, all balls (kg %1)</source>
        <translation>p, alla bollar (kg %1)</translation>
    </message>
    <message>
        <source>p (kg %1)</source>
        <translation>p (kg %1)</translation>
    </message>
    <message>
        <source>Difference, %1</source>
        <translation>Skillnad, %1</translation>
    </message>
    <message>
        <source>Balls past each foot</source>
        <translation>Bollar förbi varje fot</translation>
    </message>
    <message>
        <source>Speeds on the street</source>
        <translation>Farter på gatan</translation>
    </message>
    <message>
        <source>left at the foot</source>
        <translation>lämnat vid foten</translation>
    </message>
    <message>
        <source>balls per %1, net</source>
        <translation>bollar per %1, netto</translation>
    </message>
    <message>
        <source>Energy per unit mass, sum over all balls (%1)</source>
        <translation>Energi per massenhet, summa över alla bollar (%1)</translation>
    </message>
    <message>
        <source>E/m, sum over all balls (%1)</source>
        <translation>E/m, summa över alla bollar (%1)</translation>
    </message>
    <message>
        <source>Σ E/m, all balls (%1)</source>
        <translation>Σ E/m, alla bollar (%1)</translation>
    </message>
    <message>
        <source>Σ E/m (%1)</source>
        <translation>Σ E/m (%1)</translation>
    </message>
    <message>
        <source>Energy (kg %1)</source>
        <translation>Energi (kg %1)</translation>
    </message>
    <message>
        <source>Energy, sum over all balls (kg %1)</source>
        <translation>Energi, summa över alla bollar (kg %1)</translation>
    </message>
    <message>
        <source>E, sum over all balls (kg %1)</source>
        <translation>E, summa över alla bollar (kg %1)</translation>
    </message>
    <message>
        <source>Σ E (kg %1)</source>
        <translation>Σ E (kg %1)</translation>
    </message>
    <message>
        <source>Σ E/m</source>
        <translation>Σ E/m</translation>
    </message>
    <message>
        <source>Σ E</source>
        <translation>Σ E</translation>
    </message>
    <message>
        <source>Energy per unit mass, mean per ball (%1)</source>
        <translation>Energi per massenhet, medelvärde per boll (%1)</translation>
    </message>
    <message>
        <source>E/m, mean per ball (%1)</source>
        <translation>E/m, medelvärde per boll (%1)</translation>
    </message>
    <message>
        <source>mean E/m (%1)</source>
        <translation>medel-E/m (%1)</translation>
    </message>
    <message>
        <source>Energy, mean per ball (kg %1)</source>
        <translation>Energi, medelvärde per boll (kg %1)</translation>
    </message>
    <message>
        <source>E, mean per ball (kg %1)</source>
        <translation>E, medelvärde per boll (kg %1)</translation>
    </message>
    <message>
        <source>mean E (kg %1)</source>
        <translation>medel-E (kg %1)</translation>
    </message>
    <message>
        <source>mean E/m</source>
        <translation>medel-E/m</translation>
    </message>
    <message>
        <source>mean E</source>
        <translation>medel-E</translation>
    </message>
</context>
<context>
    <name>ab::ui::ParameterPanel</name>
    <message>
        <source>Report values</source>
        <translation>Rapportens värden</translation>
    </message>
    <message>
        <source>Restore every constant of this stage to the report&apos;s value</source>
        <translation>Återställ varje konstant i denna etapp till rapportens värde</translation>
    </message>
    <message>
        <source>Report:</source>
        <translation>Rapporten:</translation>
    </message>
    <message>
        <source>Range:</source>
        <translation>Intervall:</translation>
    </message>
    <message>
        <source>Report value:</source>
        <translation>Rapportens värde:</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Inte tillämpat: %1</translation>
    </message>
    <message>
        <source>Source:</source>
        <translation>Källa:</translation>
    </message>
    <message>
        <source>Default:</source>
        <translation>Standardvärde:</translation>
    </message>
    <message>
        <source>Default values</source>
        <translation>Standardvärden</translation>
    </message>
    <message>
        <source>Restore every constant of this stage to its default</source>
        <translation>Återställ varje konstant i denna etapp till dess standardvärde</translation>
    </message>
</context>
<context>
    <name>ab::ui::PresetActions</name>
    <message>
        <source>Position</source>
        <translation>Position</translation>
    </message>
    <message>
        <source>Velocity</source>
        <translation>Hastighet</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energi</translation>
    </message>
    <message>
        <source>Stage %1 (%2), %3 model</source>
        <translation>Etapp %1 (%2), modellen %3</translation>
    </message>
    <message>
        <source>, %1 integrator, impacts %2</source>
        <translation>, integratorn %1, stötar %2</translation>
    </message>
    <message>
        <source>, step %1 %2</source>
        <translation>, tidssteg %1 %2</translation>
    </message>
    <message>
        <source>, %1 steps.</source>
        <translation>, %1 steg.</translation>
    </message>
    <message>
        <source>Open preset...</source>
        <translation>Öppna förinställning...</translation>
    </message>
    <message>
        <source>Save preset...</source>
        <translation>Spara förinställning...</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Förinställningar</translation>
    </message>
    <message>
        <source>Stage %1: %2</source>
        <translation>Etapp %1: %2</translation>
    </message>
    <message>
        <source>Charts shown</source>
        <translation>Visade diagram</translation>
    </message>
    <message>
        <source>Opened preset: %1</source>
        <translation>Öppnade förinställningen: %1</translation>
    </message>
    <message>
        <source>Preset not opened</source>
        <translation>Förinställningen öppnades inte</translation>
    </message>
    <message>
        <source>Open preset</source>
        <translation>Öppna förinställning</translation>
    </message>
    <message>
        <source>Amazeballs preset (*.json)</source>
        <translation>Amazeballs-förinställning (*.json)</translation>
    </message>
    <message>
        <source>Save preset</source>
        <translation>Spara förinställning</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Skrev %1</translation>
    </message>
    <message>
        <source>Preset not saved</source>
        <translation>Förinställningen sparades inte</translation>
    </message>
    <message>
        <source>Momentum (two or more balls)</source>
        <translation>Rörelsemängd (två eller fler bollar)</translation>
    </message>
    <message>
        <source>Moving balls and impacts (many balls)</source>
        <translation>Rörliga bollar och stötar (många bollar)</translation>
    </message>
    <message>
        <source>Difference between the runs (with a comparison or a closed form)</source>
        <translation>Skillnad mellan körningarna (med en jämförelse eller en sluten form)</translation>
    </message>
    <message>
        <source>Spin (balls that turn, physical model)</source>
        <translation>Rotation (bollar som snurrar, fysikalisk modell)</translation>
    </message>
    <message>
        <source>Balls passing the foot of each block (street)</source>
        <translation>Bollar som passerar varje kvarters fot (gatan)</translation>
    </message>
    <message>
        <source>Speeds of the balls on the street (street)</source>
        <translation>Farterna hos bollarna på gatan (gatan)</translation>
    </message>
</context>
<context>
    <name>ab::ui::RunOptionsPanel</name>
    <message>
        <source>Model</source>
        <translation>Modell</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>located inside the step</source>
        <translation>lokaliserade inom steget</translation>
    </message>
    <message>
        <source>at the step&apos;s end (as the report)</source>
        <translation>vid stegets slut (som rapporten)</translation>
    </message>
    <message>
        <source>Impacts</source>
        <translation>Stötar</translation>
    </message>
    <message>
        <source>Step dt</source>
        <translation>Tidssteg dt</translation>
    </message>
    <message>
        <source>Length of the run in steps; the report&apos;s value by default</source>
        <translation>Körningens längd i steg; rapportens värde som standard</translation>
    </message>
    <message>
        <source>Steps</source>
        <translation>Steg</translation>
    </message>
    <message>
        <source>%1 (the model&apos;s step)</source>
        <translation>%1 (modellens tidssteg)</translation>
    </message>
    <message>
        <source>The report model has one scheme per stage, the report&apos;s own</source>
        <translation>Rapportmodellen har en metod per etapp, rapportens egen</translation>
    </message>
    <message>
        <source>How the physical model advances in time</source>
        <translation>Hur den fysikaliska modellen stegar fram i tiden</translation>
    </message>
    <message>
        <source>Where impacts are found</source>
        <translation>Var stötar hittas</translation>
    </message>
    <message>
        <source>Not applied: %1</source>
        <translation>Inte tillämpat: %1</translation>
    </message>
    <message>
        <source>off</source>
        <translation>av</translation>
    </message>
    <message>
        <source>Compare with</source>
        <translation>Jämför med</translation>
    </message>
    <message>
        <source>Where the comparison run finds impacts</source>
        <translation>Var jämförelsekörningen hittar stötar</translation>
    </message>
    <message>
        <source>Its impacts</source>
        <translation>Dess stötar</translation>
    </message>
    <message>
        <source>Runs the same stage again beside this run, from the same start and with the same constants, computed another way: ghosted in the 3D view, dotted on the charts.</source>
        <translation>Kör samma etapp en gång till bredvid den här körningen, från samma start och med samma konstanter, beräknad på ett annat sätt: som spöke i 3D-vyn, prickad i diagrammen.</translation>
    </message>
    <message>
        <source>The report model ignores the physical-only constants (%1). When this run is the report&apos;s, a physical comparison reads them as this stage holds them: their defaults unless they were set while the physical model was chosen.</source>
        <translation>Rapportmodellen bortser från konstanterna som bara den fysikaliska modellen har (%1). När den här körningen är rapportens läser en fysikalisk jämförelse dem som etappen har dem: deras standardvärden, om de inte ändrades medan den fysikaliska modellen var vald.</translation>
    </message>
    <message>
        <source>The physical model ignores the report-only constants (%1).</source>
        <translation>Den fysikaliska modellen bortser från konstanterna som bara rapportmodellen har (%1).</translation>
    </message>
    <message>
        <source>report: explicit Euler (eqs 2.12-2.16)</source>
        <translation>rapporten: explicit Euler (ekv. 2.12-2.16)</translation>
    </message>
    <message>
        <source>report: semi-implicit Euler step (eqs 2.18-2.22)</source>
        <translation>rapporten: semi-implicit Euler-steg (ekv. 2.18-2.22)</translation>
    </message>
    <message>
        <source>report: one update per frame (Appendix D)</source>
        <translation>rapporten: en uppdatering per bildruta (bilaga D)</translation>
    </message>
    <message>
        <source>report: at the step&apos;s end (Appendix A)</source>
        <translation>rapporten: i slutet av steget (bilaga A)</translation>
    </message>
    <message>
        <source>report: at the step&apos;s end, one face a step (Appendix B)</source>
        <translation>rapporten: i slutet av steget, en yta per steg (bilaga B)</translation>
    </message>
    <message>
        <source>report: at the end of each frame (Appendix D)</source>
        <translation>rapporten: i slutet av varje bildruta (bilaga D)</translation>
    </message>
    <message>
        <source>The report&apos;s rules stop at the box; the street is the physical model&apos;s (report 3.1)</source>
        <translation>Rapportens regler slutar vid kuben; gatan hör till den fysikaliska modellen (rapporten 3.1)</translation>
    </message>
    <message>
        <source>Not offered on the street: its flight is exact between events (event)</source>
        <translation>Erbjuds inte på gatan: dess flykt är exakt mellan händelserna (event)</translation>
    </message>
    <message>
        <source>Not offered for many balls: their contacts are resolved at each substep&apos;s end, without spring contacts</source>
        <translation>Erbjuds inte för många bollar: deras kontakter löses i slutet av varje delsteg, utan fjäderkontakter</translation>
    </message>
</context>
<context>
    <name>ab::ui::StabilityDialog</name>
    <message>
        <source>Stability suite</source>
        <translation>Stabilitetstester</translation>
    </message>
    <message>
        <source>Stiff and extreme runs of both models, each checked every step for energy gained, penetration, escaped balls and non-finite values. Hover a row for its note.</source>
        <translation>Styva och extrema körningar av båda modellerna, där varje körning kontrolleras i varje steg för energiökning, inträngning, bollar som rymt och icke-ändliga värden. Håll muspekaren över en rad för dess anmärkning.</translation>
    </message>
    <message>
        <source>%v of %m rows</source>
        <translation>%v av %m rader</translation>
    </message>
    <message>
        <source>Choose what to run and press Run.</source>
        <translation>Välj vad som ska köras och tryck på Kör.</translation>
    </message>
    <message>
        <source>Export CSV...</source>
        <translation>Exportera CSV...</translation>
    </message>
    <message>
        <source>Export Markdown...</source>
        <translation>Exportera Markdown...</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Stäng</translation>
    </message>
    <message>
        <source>Every case</source>
        <translation>Alla fall</translation>
    </message>
    <message>
        <source>The rows of %1</source>
        <translation>Raderna för %1</translation>
    </message>
    <message>
        <source>Case %1</source>
        <translation>Fall %1</translation>
    </message>
    <message>
        <source>R&amp;un:</source>
        <translation>&amp;Kör:</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Kör</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Filter by case, model, integrator, setting</source>
        <translation>Filtrera på fall, modell, integrator, inställning</translation>
    </message>
    <message>
        <source>All verdicts</source>
        <translation>Alla bedömningar</translation>
    </message>
    <message>
        <source>Legend:</source>
        <translation>Teckenförklaring:</translation>
    </message>
    <message>
        <source>energy grew past the limit, a ball escaped, or a value became non-finite</source>
        <translation>energin växte över gränsen, en boll rymde eller ett värde blev icke-ändligt</translation>
    </message>
    <message>
        <source>within bounds but off: energy gained or penetration beyond tolerance</source>
        <translation>inom gränserna men avvikande: energiökning eller inträngning utöver toleransen</translation>
    </message>
    <message>
        <source>held</source>
        <translation>höll</translation>
    </message>
    <message>
        <source>not in this build or not run</source>
        <translation>finns inte i denna version eller kördes inte</translation>
    </message>
    <message>
        <source>Running...</source>
        <translation>Kör...</translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation>Avbryter...</translation>
    </message>
    <message>
        <source>The suite stopped: %1</source>
        <translation>Testerna stoppades: %1</translation>
    </message>
    <message>
        <source>Done: %1</source>
        <translation>Klart: %1</translation>
    </message>
    <message>
        <source>Cancelled: %1. Nothing to export from a partial run.</source>
        <translation>Avbrutet: %1. Inget att exportera från en ofullständig körning.</translation>
    </message>
    <message>
        <source>%1 rows, %2 ok, %3 degraded, %4 failed, %5 not run</source>
        <translation>%1 rader, %2 ok, %3 försämrade, %4 underkända, %5 ej körda</translation>
    </message>
    <message>
        <source>Export Markdown</source>
        <translation>Exportera Markdown</translation>
    </message>
    <message>
        <source>Markdown (*.md)</source>
        <translation>Markdown-fil (*.md)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportera CSV</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV-tabell (*.csv)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sparade %1</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Exporten misslyckades</translation>
    </message>
</context>
<context>
    <name>ab::ui::StabilityTableModel</name>
    <message>
        <source>✖ failed</source>
        <translation>✖ underkänd</translation>
    </message>
    <message>
        <source>▲ degraded</source>
        <translation>▲ försämrad</translation>
    </message>
    <message>
        <source>ok</source>
        <translation>ok</translation>
    </message>
    <message>
        <source>– not run</source>
        <translation>– ej körd</translation>
    </message>
    <message>
        <source>yes</source>
        <translation>ja</translation>
    </message>
    <message>
        <source>no</source>
        <translation>nej</translation>
    </message>
    <message>
        <source>case</source>
        <translation>fall</translation>
    </message>
    <message>
        <source>model</source>
        <translation>modell</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrator</translation>
    </message>
    <message>
        <source>setting</source>
        <translation>inställning</translation>
    </message>
    <message>
        <source>verdict</source>
        <translation>bedömning</translation>
    </message>
    <message>
        <source>max energy gain</source>
        <translation>max energiökning</translation>
    </message>
    <message>
        <source>max penetration</source>
        <translation>max inträngning</translation>
    </message>
    <message>
        <source>escaped</source>
        <translation>rymt</translation>
    </message>
    <message>
        <source>non-finite</source>
        <translation>icke-ändligt</translation>
    </message>
    <message>
        <source>reference error</source>
        <translation>referensfel</translation>
    </message>
    <message>
        <source>dt</source>
        <translation>dt</translation>
    </message>
    <message>
        <source>CPU seconds</source>
        <translation>CPU-sekunder</translation>
    </message>
    <message>
        <source>note</source>
        <translation>anmärkning</translation>
    </message>
</context>
<context>
    <name>ab::ui::StageNavigator</name>
    <message>
        <source>Stage %1</source>
        <translation>Etapp %1</translation>
    </message>
    <message>
        <source>Report:</source>
        <translation>Rapporten:</translation>
    </message>
    <message>
        <source>Equations</source>
        <translation>Ekvationer</translation>
    </message>
    <message>
        <source>Notes on the report</source>
        <translation>Anmärkningar om rapporten</translation>
    </message>
    <message>
        <source>Stage %1: %2 (key %1)</source>
        <translation>Etapp %1: %2 (tangent %1)</translation>
    </message>
    <message>
        <source>&lt; Back</source>
        <translation>&lt; Bakåt</translation>
    </message>
    <message>
        <source>&lt; Previous stage</source>
        <translation>&lt; Föregående etapp</translation>
    </message>
    <message>
        <source>Next &gt;</source>
        <translation>Nästa &gt;</translation>
    </message>
    <message>
        <source>Next stage &gt;</source>
        <translation>Nästa etapp &gt;</translation>
    </message>
    <message>
        <source>Equation %1 of %2. Next shows the next equation.</source>
        <translation>Ekvation %1 av %2. Nästa visar nästa ekvation.</translation>
    </message>
    <message>
        <source>All %1 equations shown. Next opens the next stage.</source>
        <translation>Alla %1 ekvationer visas. Nästa öppnar nästa etapp.</translation>
    </message>
    <message>
        <source>Preset: %1</source>
        <translation>Förinställning: %1</translation>
    </message>
    <message>
        <source>No equation shown yet, %1 to come. Next shows the first.</source>
        <translation>Ingen ekvation visad än, %1 kommer. Nästa visar den första.</translation>
    </message>
    <message>
        <source>All %1 equations shown: the last stage&apos;s walk is over.</source>
        <translation>Alla %1 ekvationer visas: sista etappens genomgång är slut.</translation>
    </message>
</context>
<context>
    <name>ab::ui::StatusReadout</name>
    <message>
        <source>Wall time of one simulation step</source>
        <translation>Verklig tid för ett simuleringssteg</translation>
    </message>
    <message>
        <source>Frames drawn per second by the 3D view</source>
        <translation>Bilder per sekund som 3D-vyn ritar</translation>
    </message>
    <message>
        <source>t = %1 %2</source>
        <translation>t = %1 %2</translation>
    </message>
    <message>
        <source>E/m = -</source>
        <translation>E/m = -</translation>
    </message>
    <message>
        <source>Stopped: %1</source>
        <translation>Stoppad: %1</translation>
    </message>
    <message>
        <source>The run is complete; Play starts it again</source>
        <translation>Körningen är klar; Spela startar den igen</translation>
    </message>
    <message>
        <source>no 3D view</source>
        <translation>ingen 3D-vy</translation>
    </message>
    <message>
        <source>Paused: %1</source>
        <translation>Pausad: %1</translation>
    </message>
    <message>
        <source>Kinetic plus potential energy, summed over the balls, with the height measured from the floor: per unit mass in the report model, with the masses in the physical one</source>
        <translation>Kinetisk plus potentiell energi, summerad över bollarna, med höjden räknad från golvet: per massenhet i rapportens modell, med massorna i den fysikaliska</translation>
    </message>
    <message>
        <source>E = -</source>
        <translation>E = -</translation>
    </message>
    <message>
        <source>Details</source>
        <translation>Detaljer</translation>
    </message>
    <message>
        <source>The whole message: what happened, the rule behind it and what to change</source>
        <translation>Hela meddelandet: vad som hände, regeln bakom det och vad man kan ändra</translation>
    </message>
    <message>
        <source>ball %1 rests %2 %3 below the floor, where the floor rule of Appendix B put it in the step the velocities were zeroed, so its potential energy, and E/m, are below zero</source>
        <translation>boll %1 vilar %2 %3 under golvet, där golvregeln i bilaga B placerade den i steget då hastigheterna nollställdes, så dess lägesenergi, och E/m, är under noll</translation>
    </message>
    <message>
        <source>%1 of %2 balls lie on the floor with a velocity but do not move: Appendix D updates only balls above the floor, so a ball keeps the velocity it reached the floor with, and the kinetic energy and momentum charts go on counting it</source>
        <translation>%1 av %2 bollar ligger på golvet med en hastighet men rör sig inte: bilaga D uppdaterar bara bollar ovanför golvet, så en boll behåller hastigheten den nådde golvet med, och diagrammen för rörelseenergi och rörelsemängd fortsätter att räkna med den</translation>
    </message>
    <message>
        <source>The run stopped</source>
        <translation>Körningen stoppades</translation>
    </message>
    <message>
        <source>Paused: the health check failed</source>
        <translation>Pausad: hälsokontrollen slog larm</translation>
    </message>
    <message>
        <source>The health check failed</source>
        <translation>Hälsokontrollen slog larm</translation>
    </message>
    <message>
        <source>The report&apos;s rules at work</source>
        <translation>Rapportens regler verkar</translation>
    </message>
    <message>
        <source>A health check warning</source>
        <translation>En varning från hälsokontrollen</translation>
    </message>
    <message>
        <source>The run is complete</source>
        <translation>Körningen är klar</translation>
    </message>
    <message>
        <source>%1 per step</source>
        <translation>%1 per steg</translation>
    </message>
    <message>
        <source>Balls on the street</source>
        <translation>Bollar på gatan</translation>
    </message>
    <message>
        <source>E/m = %1 %2 a ball</source>
        <translation>E/m = %1 %2 per boll</translation>
    </message>
    <message>
        <source>E/m = %1 %2</source>
        <translation>E/m = %1 %2</translation>
    </message>
    <message>
        <source>E = %1 kg %2</source>
        <translation>E = %1 kg %2</translation>
    </message>
    <message>
        <source>fastest %1 m/s</source>
        <translation>snabbast %1 m/s</translation>
    </message>
    <message>
        <source>All %1 balls have left at the foot</source>
        <translation>Alla %1 bollar har lämnat vid foten</translation>
    </message>
    <message>
        <source>All have left at the foot</source>
        <translation>Alla har lämnat vid foten</translation>
    </message>
    <message numerus="yes">
        <source>%n fps</source>
        <translation>
            <numerusform>%n bild/s</numerusform>
            <numerusform>%n bilder/s</numerusform>
        </translation>
    </message>
    <message>
        <source>The ball has left at the foot</source>
        <translation>Bollen har lämnat vid foten</translation>
    </message>
    <message>
        <source>The ball is past the first block&apos;s foot at %1 m/s</source>
        <translation>Bollen är förbi första kvarterets fot i %1 m/s</translation>
    </message>
    <message>
        <source>The ball is on the first block at %1 m/s</source>
        <translation>Bollen är på första kvarteret i %1 m/s</translation>
    </message>
    <message>
        <source>The ball on the street</source>
        <translation>Bollen på gatan</translation>
    </message>
    <message>
        <source>%1 m/s</source>
        <translation>%1 m/s</translation>
    </message>
    <message>
        <source>%1 balls on the street, %2 past the first block&apos;s foot, %3 out at the foot; fastest %4 m/s</source>
        <translation>%1 bollar på gatan, %2 förbi första kvarterets fot, %3 ute vid foten; snabbast %4 m/s</translation>
    </message>
    <message>
        <source>%1 on the street, %2 out at the foot; fastest %3 m/s</source>
        <translation>%1 på gatan, %2 ute vid foten; snabbast %3 m/s</translation>
    </message>
    <message>
        <source>%1 out at the foot; fastest %2 m/s</source>
        <translation>%1 ute vid foten; snabbast %2 m/s</translation>
    </message>
    <message>
        <source>The ball has left at the foot at t = %1 s; the run ends there, and Play starts it again</source>
        <translation>Bollen har lämnat vid foten vid t = %1 s; körningen slutar där, och Spela startar den igen</translation>
    </message>
    <message>
        <source>All %1 balls have left at the foot by t = %2 s; the run ends there, and Play starts it again</source>
        <translation>Alla %1 bollar har lämnat vid foten vid t = %2 s; körningen slutar där, och Spela startar den igen</translation>
    </message>
    <message>
        <source>The ball has left at t = %1 s; the run is complete</source>
        <translation>Bollen har lämnat vid t = %1 s; körningen är klar</translation>
    </message>
    <message>
        <source>All %1 balls have left by t = %2 s; the run is complete</source>
        <translation>Alla %1 bollar har lämnat vid t = %2 s; körningen är klar</translation>
    </message>
    <message>
        <source>Run complete: the ball left at t = %1 s</source>
        <translation>Klar: bollen lämnade vid t = %1 s</translation>
    </message>
    <message>
        <source>Run complete: all have left by t = %1 s</source>
        <translation>Klar: alla har lämnat vid t = %1 s</translation>
    </message>
    <message>
        <source>Run complete at t = %1 s</source>
        <translation>Klar vid t = %1 s</translation>
    </message>
    <message>
        <source>%1: the report&apos;s own rule</source>
        <translation>%1: rapportens egen regel</translation>
    </message>
    <message>
        <source>– fps</source>
        <translation>– bilder/s</translation>
    </message>
    <message>
        <source>Kinetic plus potential energy per unit mass, with the height measured from the street&apos;s foot, and what the balls that left at the foot took with them: the mean over the %1 balls, as the energy chart draws it. All balls together: %2 %3</source>
        <translation>Kinetisk plus potentiell energi per massenhet, med höjden räknad från gatans fot, och det som bollarna som lämnat vid foten tog med sig: medelvärdet över de %1 bollarna, som energidiagrammet ritar det. Alla bollar tillsammans: %2 %3</translation>
    </message>
    <message>
        <source>&lt; 0.1 fps</source>
        <translation>&lt; 0.1 bilder/s</translation>
    </message>
    <message>
        <source>%1 fps</source>
        <translation>%1 bilder/s</translation>
    </message>
</context>
<context>
    <name>ab::ui::StreetCameraBar</name>
    <message>
        <source>Camera:</source>
        <translation>Kamera:</translation>
    </message>
    <message>
        <source>Low on the road past the foot, looking up the street: the advert&apos;s shot (F)</source>
        <translation>Lågt på gatan bortom foten, med blicken uppför gatan: reklamfilmens bild (F)</translation>
    </message>
    <message>
        <source>Ahead of the front of the flood, moving down the hill with it (G)</source>
        <translation>Framför flodens front, på väg nedför backen med den (G)</translation>
    </message>
    <message>
        <source>Foot</source>
        <translation>Foten</translation>
    </message>
    <message>
        <source>Side</source>
        <translation>Sidan</translation>
    </message>
    <message>
        <source>Flood</source>
        <translation>Floden</translation>
    </message>
    <message>
        <source>The whole street from the side and above, the near houses cut away (S)</source>
        <translation>Hela gatan från sidan och ovanifrån, de närmaste husen bortskurna (S)</translation>
    </message>
</context>
<context>
    <name>ab::ui::StudyDialog</name>
    <message>
        <source>Accuracy study: %1</source>
        <translation>Noggrannhetsstudie: %1</translation>
    </message>
    <message>
        <source>%v of %m runs</source>
        <translation>%v av %m körningar</translation>
    </message>
    <message>
        <source>Press Run to start.</source>
        <translation>Tryck på Kör för att börja.</translation>
    </message>
    <message>
        <source>Export CSV...</source>
        <translation>Exportera CSV...</translation>
    </message>
    <message>
        <source>Export chart...</source>
        <translation>Exportera diagram...</translation>
    </message>
    <message>
        <source>Close</source>
        <translation>Stäng</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;No accuracy study for %1 with these constants.&lt;/b&gt;&lt;/p&gt;&lt;p&gt;The study measures each integrator&apos;s error against the scene&apos;s exact motion, and here there is none: %2&lt;/p&gt;&lt;p&gt;It applies to bounce1d (no drag, linear or quadratic drag), box3d without drag or friction, and two-balls in the symmetric head-on meeting. The stability suite (Tools menu) covers every scene.&lt;/p&gt;</source>
        <translation>&lt;p&gt;&lt;b&gt;Ingen noggrannhetsstudie för %1 med dessa konstanter.&lt;/b&gt;&lt;/p&gt;&lt;p&gt;Studien mäter varje integrators fel mot etappens exakta rörelse, och här finns ingen sådan: %2&lt;/p&gt;&lt;p&gt;Den gäller bounce1d (utan luftmotstånd eller med linjärt eller kvadratiskt luftmotstånd), box3d utan luftmotstånd och friktion samt two-balls i det symmetriska mötet rakt framifrån. Stabilitetstesterna (menyn Verktyg) omfattar alla etapper.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&amp;t end (%1)</source>
        <translation>&amp;sluttid (%1)</translation>
    </message>
    <message>
        <source>Each run goes from t = 0 to this time.</source>
        <translation>Varje körning går från t = 0 till denna tidpunkt.</translation>
    </message>
    <message>
        <source>dt &amp;from</source>
        <translation>dt &amp;från</translation>
    </message>
    <message>
        <source>The coarsest step (the sampling interval for event-driven).</source>
        <translation>Det grövsta tidssteget (samplingsintervallet för den händelsestyrda metoden).</translation>
    </message>
    <message>
        <source>&amp;to</source>
        <translation>&amp;till</translation>
    </message>
    <message>
        <source>The finest step; steps between are spaced evenly on a log scale.</source>
        <translation>Det finaste tidssteget; stegen däremellan fördelas jämnt på en logaritmisk skala.</translation>
    </message>
    <message>
        <source>&amp;per decade</source>
        <translation>&amp;per dekad</translation>
    </message>
    <message>
        <source>Steps tried per factor of ten.</source>
        <translation>Antal tidssteg som prövas per tiopotens.</translation>
    </message>
    <message>
        <source>&amp;repeats</source>
        <translation>&amp;upprepningar</translation>
    </message>
    <message>
        <source>Timed repeats of each run; the median CPU time is shown.</source>
        <translation>Tidtagna upprepningar av varje körning; medianen av CPU-tiden visas.</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Kör</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Avbryt</translation>
    </message>
    <message>
        <source>Running...</source>
        <translation>Kör...</translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation>Avbryter...</translation>
    </message>
    <message>
        <source>%1 of %2: %3 at dt %4</source>
        <translation>%1 av %2: %3 med dt %4</translation>
    </message>
    <message>
        <source>The study stopped: %1</source>
        <translation>Studien stoppades: %1</translation>
    </message>
    <message>
        <source>Done: %1 runs against %2.</source>
        <translation>Klart: %1 körningar mot %2.</translation>
    </message>
    <message>
        <source>Cancelled after %1 runs; nothing to export from a partial study.</source>
        <translation>Avbrutet efter %1 körningar; inget att exportera från en ofullständig studie.</translation>
    </message>
    <message>
        <source>The chart appears when the study is done.</source>
        <translation>Diagrammet visas när studien är klar.</translation>
    </message>
    <message>
        <source>Export chart</source>
        <translation>Exportera diagram</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG image (*.svg)</source>
        <translation>PNG-bild (*.png);;SVG-bild (*.svg)</translation>
    </message>
    <message>
        <source>Export CSV</source>
        <translation>Exportera CSV</translation>
    </message>
    <message>
        <source>CSV table (*.csv)</source>
        <translation>CSV-tabell (*.csv)</translation>
    </message>
    <message>
        <source>Saved %1</source>
        <translation>Sparade %1</translation>
    </message>
    <message>
        <source>Export failed</source>
        <translation>Exporten misslyckades</translation>
    </message>
    <message>
        <source>Error against run time of the physical model&apos;s integrators on %1, each run measured against the scene&apos;s exact motion, with impacts located inside the step and found at its end side by side. Lower left is better; where a line is straight its slope is the order, and a steeper line is a higher order.</source>
        <translation>Fel mot beräkningstid för den fysikaliska modellens integratorer för %1, där varje körning mäts mot etappens exakta rörelse, med stötar lokaliserade inuti steget och funna vid stegets slut sida vid sida. Längre ned till vänster är bättre; där en linje är rak är dess lutning ordningen, och en brantare linje innebär högre ordning.</translation>
    </message>
    <message>
        <source>In free fall the flight is a parabola, which Verlet and RK4 follow exactly; the linear drag b below (%1 when the scene has none) gives every integrator an error to show. With b = 0 the study is of the scene as it is.</source>
        <translation>I fritt fall är banan en parabel, som Verlet och RK4 följer exakt; det linjära luftmotståndet b nedan (%1 när etappen saknar det) ger varje integrator ett fel att visa. Med b = 0 studeras etappen som den är.</translation>
    </message>
    <message>
        <source>Between impacts the flight is a parabola, which Verlet and RK4 follow exactly: their error is the impacts&apos; alone, and round-off at the finest steps.</source>
        <translation>Mellan stötarna är banan en parabel, som Verlet och RK4 följer exakt: deras fel kommer enbart från stötarna, och från avrundning vid de finaste stegen.</translation>
    </message>
    <message>
        <source>&amp;drag b (%1)</source>
        <translation>&amp;luftmotstånd b (%1)</translation>
    </message>
    <message>
        <source>Linear air drag, force -b v (report equation 3.1); 0: none, where Verlet and RK4 are exact.</source>
        <translation>Linjärt luftmotstånd, kraften -b v (rapportens ekvation 3.1); 0: inget, då Verlet och RK4 är exakta.</translation>
    </message>
</context>
<context>
    <name>ab::ui::StudyTableModel</name>
    <message>
        <source>integrator</source>
        <translation>integrator</translation>
    </message>
    <message>
        <source>impacts</source>
        <translation>stötar</translation>
    </message>
    <message>
        <source>dt (%1)</source>
        <translation>dt (%1)</translation>
    </message>
    <message>
        <source>max error (%1)</source>
        <translation>max fel (%1)</translation>
    </message>
    <message>
        <source>relative error</source>
        <translation>relativt fel</translation>
    </message>
    <message>
        <source>CPU seconds</source>
        <translation>CPU-sekunder</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>steg</translation>
    </message>
</context>
<context>
    <name>ab::ui::TransportBar</name>
    <message>
        <source>Step</source>
        <translation>Steg</translation>
    </message>
    <message>
        <source>One step (Right arrow)</source>
        <translation>Ett steg (högerpil)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Återställ</translation>
    </message>
    <message>
        <source>Back to the start (R)</source>
        <translation>Tillbaka till början (R)</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Hastighet</translation>
    </message>
    <message>
        <source>Simulated time per real second: 0.1x to 10x real time</source>
        <translation>Simulerad tid per verklig sekund: 0,1x till 10x verklig tid</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Paus</translation>
    </message>
    <message>
        <source>Play</source>
        <translation>Spela</translation>
    </message>
    <message>
        <source>Play or pause (Space)</source>
        <translation>Spela eller pausa (mellanslag)</translation>
    </message>
    <message>
        <source>t = %1 %2 (live)</source>
        <translation>t = %1 %2 (direkt)</translation>
    </message>
    <message>
        <source>Drag to look back through the recorded run; the right end is live. Play or Step there goes on from the moment shown: the run forks, and what came after is dropped</source>
        <translation>Dra för att se tillbaka i den inspelade körningen; högra änden är direkt. Spela eller Steg där fortsätter från det visade ögonblicket: körningen förgrenas, och det som kom efter kastas</translation>
    </message>
    <message>
        <source>t = %1 of %2 %3 (looking back: Play goes on from here)</source>
        <translation>t = %1 av %2 %3 (tillbakablick: Spela fortsätter härifrån)</translation>
    </message>
    <message>
        <source>%1× real time</source>
        <translation>%1× realtid</translation>
    </message>
    <message>
        <source>t = %1 of %2 %3</source>
        <translation>t = %1 av %2 %3</translation>
    </message>
    <message>
        <source>%1×, plays at %2×</source>
        <translation>%1×, spelas i %2×</translation>
    </message>
    <message>
        <source>The run&apos;s steps take longer to compute than the time they show: it plays at %1× real time, in slow motion</source>
        <translation>Körningens steg tar längre tid att räkna ut än den tid de visar: den spelas i %1× realtid, i ultrarapid</translation>
    </message>
</context>
<context>
    <name>ab::ui::WindowShell</name>
    <message>
        <source>Lecture mode</source>
        <translation>Föreläsningsläge</translation>
    </message>
    <message>
        <source>Ctrl+L</source>
        <translation>Ctrl+L</translation>
    </message>
    <message>
        <source>Full screen</source>
        <translation>Helskärm</translation>
    </message>
    <message>
        <source>Theme</source>
        <translation>Tema</translation>
    </message>
    <message>
        <source>Colour-blind-safe palette</source>
        <translation>Färgblindsäker palett</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>S&amp;pråk</translation>
    </message>
</context>
<context>
    <name>core</name>
    <message>
        <source>1/step^2</source>
        <translation>1/steg^2</translation>
    </message>
    <message>
        <source>2.1.1, 2.2.1, Appendix A, Figure 2.5</source>
        <translation>2.1.1, 2.2.1, Bilaga A, Figur 2.5</translation>
    </message>
    <message>
        <source>2.1.2, Appendix C, eqs 2.4-2.11</source>
        <translation>2.1.2, Bilaga C, ekv. 2.4-2.11</translation>
    </message>
    <message>
        <source>2.2.1 (Zeno)</source>
        <translation>2.2.1 (Zeno)</translation>
    </message>
    <message>
        <source>2.2.2 (Zeno)</source>
        <translation>2.2.2 (Zeno)</translation>
    </message>
    <message>
        <source>2.2.2, Appendix B, Appendix C (propagation), Figures 2.6-2.7</source>
        <translation>2.2.2, Bilaga B, Bilaga C (propagation), Figur 2.6-2.7</translation>
    </message>
    <message>
        <source>2.3, Appendix D, eqs 2.23-2.31, Figure 3.1</source>
        <translation>2.3, Bilaga D, ekv. 2.23-2.31, Figur 3.1</translation>
    </message>
    <message>
        <source>3.1 (air resistance)</source>
        <translation>3.1 (luftmotstånd)</translation>
    </message>
    <message>
        <source>A ball bouncing in one dimension</source>
        <translation>En boll som studsar i en dimension</translation>
    </message>
    <message>
        <source>A ball falls from rest and bounces on a floor. Flight follows dv/dt = -g and dx/dt = v (eqs 2.1-2.2); an impact reverses and shrinks the velocity, v1 = -k v0 (eq 2.3). The bounces come ever faster (Zeno behaviour), so the report stops the ball after a fixed number of bounces.</source>
        <translation>En boll faller från vila och studsar mot ett golv. I luften gäller dv/dt = -g och dx/dt = v (ekv. 2.1-2.2); en stöt vänder och minskar hastigheten, v1 = -k v0 (ekv. 2.3). Studsarna kommer allt tätare (Zeno-beteende), så rapporten stoppar bollen efter ett bestämt antal studsar.</translation>
    </message>
    <message>
        <source>A floor hit is p &lt;= 0 and v &lt;= 0 at the start of a step. That step also sets the stored position of the contact state to 0, and when the bounce counter exceeds max_bounces the contact state and every later state are set to zero.</source>
        <translation>En golvträff är p &lt;= 0 och v &lt;= 0 i början av ett steg. Det steget sätter också kontakttillståndets lagrade position till 0, och när studsräknaren överskrider max_bounces sätts kontakttillståndet och varje senare tillstånd till noll.</translation>
    </message>
    <message>
        <source>Appendix A</source>
        <translation>Bilaga A</translation>
    </message>
    <message>
        <source>Appendix B</source>
        <translation>Bilaga B</translation>
    </message>
    <message>
        <source>Appendix C</source>
        <translation>Bilaga C</translation>
    </message>
    <message>
        <source>Appendix D</source>
        <translation>Bilaga D</translation>
    </message>
    <message>
        <source>At the floor the new vertical velocity is -k v - g dt (g the magnitude; the code adds grav dt with grav = -9.82) and the position restarts from the floor, p[new] = v[new] dt; the contact state&apos;s stored coordinate is set to the face it hit.</source>
        <translation>Vid golvet blir den nya vertikala hastigheten -k v - g dt (g är beloppet; koden adderar grav dt med grav = -9.82) och positionen börjar om från golvet, p[new] = v[new] dt; kontakttillståndets lagrade koordinat sätts till den sida som träffades.</translation>
    </message>
    <message>
        <source>Before settling on a coefficient of restitution the report considered spring equations for the bounce. The physical model offers them as `contact` 1 (y&apos;&apos; = -g - k_s y - c_s v below the floor) and 2 (Hertz, y&apos;&apos; = -g + k_h d^1.5 - c_h d^0.25 v with d = -y); their damping gives the restitution k and their stiffness the contact time t_c, and a stiff spring makes the ODE stiff.</source>
        <translation>Innan rapporten valde en studskoefficient övervägdes fjäderekvationer för studsen. Den fysikaliska modellen erbjuder dem som `contact` 1 (y&apos;&apos; = -g - k_s y - c_s v under golvet) och 2 (Hertz, y&apos;&apos; = -g + k_h d^1.5 - c_h d^0.25 v med d = -y); deras dämpning ger studskoefficienten k och deras styvhet kontakttiden t_c, och en styv fjäder gör differentialekvationen styv.</translation>
    </message>
    <message>
        <source>Each ball moves with the stage-2 rules (propagation). propagation works on a copy, so unlike stage 2 the recorded contact state keeps its unclamped coordinate.</source>
        <translation>Varje boll rör sig enligt reglerna i etapp 2 (propagation). propagation arbetar på en kopia, så till skillnad från etapp 2 behåller det inspelade kontakttillståndet sin obegränsade koordinat.</translation>
    </message>
    <message>
        <source>Event-driven, exact</source>
        <translation>Händelsestyrd, exakt</translation>
    </message>
    <message>
        <source>Every contact adds one to a counter; once it exceeds max_bounces the state the step started from and every later state are set to zero.</source>
        <translation>Varje kontakt ökar en räknare med ett; när den överskrider max_bounces sätts tillståndet som steget började från och varje senare tillstånd till noll.</translation>
    </message>
    <message>
        <source>Explicit Euler</source>
        <translation>Explicit Euler</translation>
    </message>
    <message>
        <source>Implicit Euler</source>
        <translation>Implicit Euler</translation>
    </message>
    <message>
        <source>Implicit midpoint</source>
        <translation>Implicit mittpunktsmetod</translation>
    </message>
    <message>
        <source>In the published code three.js&apos;s projectOnVector changes the vector it is called on, so v1n and v1t are one object and the decomposition collapses; the product implements the report&apos;s equations.</source>
        <translation>I den publicerade koden ändrar three.js projectOnVector den vektor den anropas på, så v1n och v1t blir samma objekt och uppdelningen faller ihop; programmet implementerar rapportens ekvationer.</translation>
    </message>
    <message>
        <source>Many balls in a box</source>
        <translation>Många bollar i en kub</translation>
    </message>
    <message>
        <source>Many balls start in a small cube at the centre of a 100-wide box with random velocities. The report&apos;s WebGL model updates once per frame: walls reverse and damp the velocity, and ball pairs closer than 2.2 r collide along their normal with a fixed tangent (eqs 2.23-2.31).</source>
        <translation>Många bollar startar i en liten kub i mitten av en kub med sidan 100 och slumpade hastigheter. Rapportens WebGL-modell uppdateras en gång per bildruta: väggar vänder och dämpar hastigheten, och bollpar närmare än 2.2 r kolliderar längs sin normal med en fast tangent (ekv. 2.23-2.31).</translation>
    </message>
    <message>
        <source>One ball in a box</source>
        <translation>En boll i en kub</translation>
    </message>
    <message>
        <source>One branch per step, in this order: floor y &lt;= 0, wall x &lt;= 0, wall x &gt;= box, wall z &lt;= 0, wall z &gt;= box, else free flight. A corner hit is handled one face per step.</source>
        <translation>En gren per steg, i denna ordning: golv y &lt;= 0, vägg x &lt;= 0, vägg x &gt;= box, vägg z &lt;= 0, vägg z &gt;= box, annars fri flykt. En hörnträff hanteras en sida per steg.</translation>
    </message>
    <message>
        <source>One counter, shared by both balls, counts every floor and wall contact and every swap; once it exceeds max_events both velocities are set to zero in the state the step started from and in every later state, while positions go on being computed.</source>
        <translation>En räknare, gemensam för båda bollarna, räknar varje golv- och väggkontakt och varje byte; när den överskrider max_events sätts båda hastigheterna till noll i tillståndet som steget började från och i varje senare tillstånd, medan positionerna fortsätter att beräknas.</translation>
    </message>
    <message>
        <source>Runge-Kutta 4</source>
        <translation>Runge-Kutta 4</translation>
    </message>
    <message>
        <source>Symplectic Euler</source>
        <translation>Symplektisk Euler</translation>
    </message>
    <message>
        <source>The ball is thrown sideways inside a 300 x 300 x 300 box with one corner at the origin and y up. Five faces are checked (no ceiling); a hit reverses the velocity along that face&apos;s axis and shrinks it by k, while the other axes fly on (eqs 2.17-2.22).</source>
        <translation>Bollen kastas åt sidan inuti en kub på 300 x 300 x 300 med ett hörn i origo och y uppåt. Fem sidor kontrolleras (inget tak); en träff vänder hastigheten längs sidans axel och minskar den med k, medan de andra axlarna fortsätter (ekv. 2.17-2.22).</translation>
    </message>
    <message>
        <source>The code counts time in steps (dt = 1) with gravity 0.0982 per step^2; the text&apos;s g = 9.82 is the same physics with the step read as 0.1 s.</source>
        <translation>Koden räknar tiden i steg (dt = 1) med gravitationen 0.0982 per steg^2; textens g = 9.82 är samma fysik med steget läst som 0.1 s.</translation>
    </message>
    <message>
        <source>The code&apos;s distance uses the y difference twice and no z difference; the product uses the Euclidean distance the code intends.</source>
        <translation>Kodens avstånd använder y-skillnaden två gånger och ingen z-skillnad; programmet använder det euklidiska avstånd som koden avser.</translation>
    </message>
    <message>
        <source>The code&apos;s literal 49 and -48 are box/2 - r and one radius above the floor; its push of 1 unit along the normal is one radius. With the report&apos;s r = 1 they are the same.</source>
        <translation>Kodens konstanter 49 och -48 är box/2 - r och en radie ovanför golvet; dess förflyttning på 1 enhet längs normalen är en radie. Med rapportens r = 1 är de desamma.</translation>
    </message>
    <message>
        <source>The equations and the refactored function propagation (Appendix C) move the position with the new velocity; the older listing of Appendix B uses the old one. The product follows the equations.</source>
        <translation>Ekvationerna och den omskrivna funktionen propagation (Bilaga C) flyttar positionen med den nya hastigheten; den äldre listningen i Bilaga B använder den gamla. Programmet följer ekvationerna.</translation>
    </message>
    <message>
        <source>The fixed tangent is undefined when n.z = 0. The product uses the same direction written as t = (0.3 n.z, 0.3 n.z, -0.3 (n.x + n.y)), which equals the report&apos;s up to sign (projections do not change) and tends to (0, 0, 1) as n.z -&gt; 0; when n.x + n.y = 0 too, every tz satisfies eq 2.24 and t = (1, 1, 0)/sqrt(2) is used.</source>
        <translation>Den fasta tangenten är odefinierad när n.z = 0. Programmet använder samma riktning skriven som t = (0.3 n.z, 0.3 n.z, -0.3 (n.x + n.y)), som är lika med rapportens sånär som på tecknet (projektionerna ändras inte) och går mot (0, 0, 1) när n.z -&gt; 0; när även n.x + n.y = 0 uppfyller varje tz ekv. 2.24 och t = (1, 1, 0)/sqrt(2) används.</translation>
    </message>
    <message>
        <source>The report prints it without the /2 that eq 2.6 and the code have; the /2 is used here.</source>
        <translation>Rapporten skriver den utan det /2 som ekv. 2.6 och koden har; här används /2.</translation>
    </message>
    <message>
        <source>The report prints p[new] = p[old] * v[old] * dt; its code (and intent) is p[new] = p[old] + v[old] dt, which is what runs here.</source>
        <translation>Rapporten skriver p[new] = p[old] * v[old] * dt; dess kod (och avsikt) är p[new] = p[old] + v[old] dt, vilket är vad som körs här.</translation>
    </message>
    <message>
        <source>The report prints v1n&apos; + v2n&apos; - v2n&apos;; the intent (and code) is v1n&apos; + v2n&apos; - v2n&apos;&apos;.</source>
        <translation>Rapporten skriver v1n&apos; + v2n&apos; - v2n&apos;; avsikten (och koden) är v1n&apos; + v2n&apos; - v2n&apos;&apos;.</translation>
    </message>
    <message>
        <source>The report&apos;s code does not use eqs 2.4-2.11 here: when the centres are closer than 2r after a step it swaps the two velocities and multiplies them by 0.95 (e), with no test that the balls approach, so the swap can repeat while they still overlap.</source>
        <translation>Rapportens kod använder inte ekv. 2.4-2.11 här: när centrumen är närmare än 2r efter ett steg byter den plats på de två hastigheterna och multiplicerar dem med 0.95 (e), utan att pröva att bollarna närmar sig, så bytet kan upprepas medan de fortfarande överlappar.</translation>
    </message>
    <message>
        <source>Two balls colliding</source>
        <translation>Två bollar som kolliderar</translation>
    </message>
    <message>
        <source>Two balls start at opposite sides of the box and meet head-on along z. The textbook collision splits each velocity into a normal part along the line of centres and a tangential part: tangential parts are kept, normal parts follow momentum conservation and restitution e (eqs 2.4-2.11). The report&apos;s own code instead swaps the two velocities and scales them by 0.95.</source>
        <translation>Två bollar startar på motsatta sidor av kuben och möts rakt framifrån längs z. Lärobokens kollision delar varje hastighet i en normaldel längs centrumlinjen och en tangentiell del: de tangentiella delarna behålls, normaldelarna följer rörelsemängdens bevarande och stötkoefficienten e (ekv. 2.4-2.11). Rapportens egen kod byter i stället plats på de två hastigheterna och skalar dem med 0.95.</translation>
    </message>
    <message>
        <source>Velocities are normalised before the projection and the results get swapped speeds: ball 1 leaves with 0.95 |v2|, ball 2 with 0.95 |v1|. A zero velocity stays zero.</source>
        <translation>Hastigheterna normaliseras före projektionen och resultaten får varandras fart: boll 1 lämnar med 0.95 |v2|, boll 2 med 0.95 |v1|. En hastighet som är noll förblir noll.</translation>
    </message>
    <message>
        <source>Velocity Verlet</source>
        <translation>Hastighets-Verlet</translation>
    </message>
    <message>
        <source>Zeno</source>
        <translation>Zeno</translation>
    </message>
    <message>
        <source>a ball with more bounces than this, near the floor, is put to rest on it</source>
        <translation>en boll med fler studsar än så, nära golvet, läggs till vila på det</translation>
    </message>
    <message>
        <source>a floor impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)</source>
        <translation>en golvstöt långsammare än så studsar inte: bollen vilar (0: studsa till Zeno-tiden)</translation>
    </message>
    <message>
        <source>a rebound that would rise less than this ends at rest (restitution threshold), at walls and between balls</source>
        <translation>en studs som skulle stiga mindre än så slutar i vila (tröskel för studsen), vid väggar och mellan bollar</translation>
    </message>
    <message>
        <source>along the axis of the wall that was hit</source>
        <translation>längs axeln för väggen som träffades</translation>
    </message>
    <message>
        <source>an impact slower than this does not rebound: the ball rests (0: bounce to the Zeno time)</source>
        <translation>en stöt långsammare än så studsar inte: bollen vilar (0: studsa till Zeno-tiden)</translation>
    </message>
    <message>
        <source>and moves on</source>
        <translation>och fortsätter</translation>
    </message>
    <message>
        <source>at the floor the velocity reverses and shrinks by k</source>
        <translation>vid golvet vänder hastigheten och minskar med k</translation>
    </message>
    <message>
        <source>ball 1 start position</source>
        <translation>startposition för boll 1</translation>
    </message>
    <message>
        <source>ball 1 start velocity</source>
        <translation>starthastighet för boll 1</translation>
    </message>
    <message>
        <source>ball 1&apos;s normal part after</source>
        <translation>normaldelen för boll 1 efteråt</translation>
    </message>
    <message>
        <source>ball 1&apos;s normal velocity after</source>
        <translation>normalhastigheten för boll 1 efteråt</translation>
    </message>
    <message>
        <source>ball 1&apos;s velocity after</source>
        <translation>hastigheten för boll 1 efteråt</translation>
    </message>
    <message>
        <source>ball 2 start position</source>
        <translation>startposition för boll 2</translation>
    </message>
    <message>
        <source>ball 2 start velocity</source>
        <translation>starthastighet för boll 2</translation>
    </message>
    <message>
        <source>ball 2&apos;s normal part after</source>
        <translation>normaldelen för boll 2 efteråt</translation>
    </message>
    <message>
        <source>ball 2&apos;s normal velocity after</source>
        <translation>normalhastigheten för boll 2 efteråt</translation>
    </message>
    <message>
        <source>ball 2&apos;s velocity after</source>
        <translation>hastigheten för boll 2 efteråt</translation>
    </message>
    <message>
        <source>ball radius</source>
        <translation>bollens radie</translation>
    </message>
    <message>
        <source>ball radius; contact when centres are closer than 2r</source>
        <translation>bollens radie; kontakt när centrumen är närmare än 2r</translation>
    </message>
    <message>
        <source>ball-ball restitution along the line of centres (the report also damps the components along a wall with it)</source>
        <translation>stötkoefficient mellan bollar längs centrumlinjen (rapporten dämpar också komponenterna längs en vägg med den)</translation>
    </message>
    <message>
        <source>ball-ball restitution; the report&apos;s code scales the swapped velocities by it</source>
        <translation>stötkoefficient mellan bollar; rapportens kod skalar de bytta hastigheterna med den</translation>
    </message>
    <message>
        <source>coefficient of restitution at floor and walls</source>
        <translation>studskoefficient vid golv och väggar</translation>
    </message>
    <message>
        <source>coefficient of restitution at the floor: v1 = -k v0</source>
        <translation>studskoefficient vid golvet: v1 = -k v0</translation>
    </message>
    <message>
        <source>duration of one spring contact (contact 1 or 2); with k it sets stiffness and damping</source>
        <translation>varaktigheten av en fjäderkontakt (contact 1 eller 2); tillsammans med k bestämmer den styvhet och dämpning</translation>
    </message>
    <message>
        <source>eq 2.1, 2.15</source>
        <translation>ekv. 2.1, 2.15</translation>
    </message>
    <message>
        <source>eq 2.12</source>
        <translation>ekv. 2.12</translation>
    </message>
    <message>
        <source>eq 2.16</source>
        <translation>ekv. 2.16</translation>
    </message>
    <message>
        <source>eq 2.17</source>
        <translation>ekv. 2.17</translation>
    </message>
    <message>
        <source>eq 2.19</source>
        <translation>ekv. 2.19</translation>
    </message>
    <message>
        <source>eq 2.3, 2.13</source>
        <translation>ekv. 2.3, 2.13</translation>
    </message>
    <message>
        <source>eq 2.3, Appendix D</source>
        <translation>ekv. 2.3, Bilaga D</translation>
    </message>
    <message>
        <source>eq 2.30</source>
        <translation>ekv. 2.30</translation>
    </message>
    <message>
        <source>eq 2.31</source>
        <translation>ekv. 2.31</translation>
    </message>
    <message>
        <source>eq 2.4 (any masses)</source>
        <translation>ekv. 2.4 (godtyckliga massor)</translation>
    </message>
    <message>
        <source>eq 2.5</source>
        <translation>ekv. 2.5</translation>
    </message>
    <message>
        <source>eqs 2.18-2.22</source>
        <translation>ekv. 2.18-2.22</translation>
    </message>
    <message>
        <source>eqs 2.24-2.25</source>
        <translation>ekv. 2.24-2.25</translation>
    </message>
    <message>
        <source>eqs 2.28-2.31, Appendix D</source>
        <translation>ekv. 2.28-2.31, Bilaga D</translation>
    </message>
    <message>
        <source>explicit Euler step of the velocity (g signed, down negative)</source>
        <translation>explicit Euler-steg för hastigheten (g med tecken, nedåt negativt)</translation>
    </message>
    <message>
        <source>floor contact of the physical model: 0 impulse v1 = -k v0 (eq 2.3), 1 linear spring-dashpot, 2 Hertz spring with damping; springs take their damping from k</source>
        <translation>golvkontakt i den fysikaliska modellen: 0 impuls v1 = -k v0 (ekv. 2.3), 1 linjär fjäder med dämpare, 2 Hertz-fjäder med dämpning; fjädrarna får sin dämpning från k</translation>
    </message>
    <message>
        <source>floor hit: bounce, no gravity in that step</source>
        <translation>golvträff: studs, ingen gravitation i det steget</translation>
    </message>
    <message>
        <source>floor hit: leave the floor with the new velocity</source>
        <translation>golvträff: lämna golvet med den nya hastigheten</translation>
    </message>
    <message>
        <source>frame</source>
        <translation>bildruta</translation>
    </message>
    <message>
        <source>free fall</source>
        <translation>fritt fall</translation>
    </message>
    <message>
        <source>free fall: position moves with the OLD velocity</source>
        <translation>fritt fall: positionen flyttas med den GAMLA hastigheten</translation>
    </message>
    <message>
        <source>free flight: gravity is the only force</source>
        <translation>fri flykt: gravitationen är den enda kraften</translation>
    </message>
    <message>
        <source>gravity per frame; the code subtracts 9.82/1000 from dy each frame</source>
        <translation>gravitation per bildruta; koden drar av 9.82/1000 från dy varje bildruta</translation>
    </message>
    <message>
        <source>kg</source>
        <translation>kg</translation>
    </message>
    <message>
        <source>kg/m</source>
        <translation>kg/m</translation>
    </message>
    <message>
        <source>kg/s</source>
        <translation>kg/s</translation>
    </message>
    <message>
        <source>kg/step</source>
        <translation>kg/steg</translation>
    </message>
    <message>
        <source>kg/unit</source>
        <translation>kg/enhet</translation>
    </message>
    <message>
        <source>linear air drag on each ball, force -b v (0: none)</source>
        <translation>linjärt luftmotstånd på varje boll, kraften -b v (0: inget)</translation>
    </message>
    <message>
        <source>linear air drag, force -b v (0: none)</source>
        <translation>linjärt luftmotstånd, kraften -b v (0: inget)</translation>
    </message>
    <message>
        <source>m</source>
        <translation>m</translation>
    </message>
    <message>
        <source>m/s</source>
        <translation>m/s</translation>
    </message>
    <message>
        <source>m/s^2</source>
        <translation>m/s^2</translation>
    </message>
    <message>
        <source>magnitude of gravity (down is -y)</source>
        <translation>gravitationens belopp (nedåt är -y)</translation>
    </message>
    <message>
        <source>magnitude of gravity; the report&apos;s code scales 9.82 to 0.0982 per step^2 with dt = 1</source>
        <translation>gravitationens belopp; rapportens kod skalar 9.82 till 0.0982 per steg^2 med dt = 1</translation>
    </message>
    <message>
        <source>mass of ball 1; momentum m1 v1 + m2 v2 is conserved in every collision</source>
        <translation>massan för boll 1; rörelsemängden m1 v1 + m2 v2 bevaras i varje kollision</translation>
    </message>
    <message>
        <source>mass of ball 2</source>
        <translation>massan för boll 2</translation>
    </message>
    <message>
        <source>mass of the ball; with drag it sets the terminal speed sqrt(m g / c)</source>
        <translation>bollens massa; med luftmotstånd bestämmer den gränshastigheten sqrt(m g / c)</translation>
    </message>
    <message>
        <source>momentum along the normal</source>
        <translation>rörelsemängd längs normalen</translation>
    </message>
    <message>
        <source>momentum is conserved (equal masses)</source>
        <translation>rörelsemängden bevaras (lika massor)</translation>
    </message>
    <message>
        <source>normal along the line of centres</source>
        <translation>normal längs centrumlinjen</translation>
    </message>
    <message>
        <source>number of balls (the report&apos;s figure shows 200)</source>
        <translation>antal bollar (rapportens figur visar 200)</translation>
    </message>
    <message>
        <source>position changes with velocity</source>
        <translation>positionen ändras med hastigheten</translation>
    </message>
    <message>
        <source>quadratic air drag on each ball, force -c |v| v (0: none)</source>
        <translation>kvadratiskt luftmotstånd på varje boll, kraften -c |v| v (0: inget)</translation>
    </message>
    <message>
        <source>quadratic air drag, force -c |v| v (0: none)</source>
        <translation>kvadratiskt luftmotstånd, kraften -c |v| v (0: inget)</translation>
    </message>
    <message>
        <source>report 1.2</source>
        <translation>rapporten 1.2</translation>
    </message>
    <message>
        <source>restitution along the normal</source>
        <translation>studs längs normalen</translation>
    </message>
    <message>
        <source>restitution of the velocity component normal to a wall or floor</source>
        <translation>studskoefficient för hastighetskomponenten vinkelrät mot en vägg eller ett golv</translation>
    </message>
    <message>
        <source>s</source>
        <translation>s</translation>
    </message>
    <message>
        <source>seed of the random start positions, velocities and colours</source>
        <translation>frö för de slumpade startpositionerna, hastigheterna och färgerna</translation>
    </message>
    <message>
        <source>side of the box, centred at the origin; centres stay within box/2 - r of the centre</source>
        <translation>kubens sida, centrerad i origo; centrumen håller sig inom box/2 - r från mitten</translation>
    </message>
    <message>
        <source>side of the cubic box (corner at the origin)</source>
        <translation>sidan av kuben (hörn i origo)</translation>
    </message>
    <message>
        <source>smooth balls: tangential part kept</source>
        <translation>släta bollar: den tangentiella delen behålls</translation>
    </message>
    <message>
        <source>spring stiffness per unit mass (Hertz: per unit^1/2); 0 takes it from contact_time</source>
        <translation>fjäderstyvhet per massenhet (Hertz: per enhet^1/2); 0 tar den från contact_time</translation>
    </message>
    <message>
        <source>start height of the ball above the floor</source>
        <translation>bollens starthöjd över golvet</translation>
    </message>
    <message>
        <source>start position (x, y, z), y up</source>
        <translation>startposition (x, y, z), y uppåt</translation>
    </message>
    <message>
        <source>start velocity (x, y, z)</source>
        <translation>starthastighet (x, y, z)</translation>
    </message>
    <message>
        <source>start vertical velocity, up positive</source>
        <translation>vertikal starthastighet, uppåt positiv</translation>
    </message>
    <message>
        <source>step</source>
        <translation>steg</translation>
    </message>
    <message>
        <source>tangential parts kept</source>
        <translation>de tangentiella delarna behålls</translation>
    </message>
    <message>
        <source>that axis moves with the NEW velocity</source>
        <translation>den axeln flyttas med den NYA hastigheten</translation>
    </message>
    <message>
        <source>the remaining horizontal axis is unchanged</source>
        <translation>den återstående horisontella axeln är oförändrad</translation>
    </message>
    <message>
        <source>the report zeroes both velocities once more than this many contacts and swaps have happened</source>
        <translation>rapporten nollställer båda hastigheterna när fler kontakter och byten än så har skett</translation>
    </message>
    <message>
        <source>the report zeroes the ball once more than this many bounces have happened (against Zeno)</source>
        <translation>rapporten nollställer bollen när fler studsar än så har skett (mot Zeno)</translation>
    </message>
    <message>
        <source>the report zeroes the ball once more than this many floor and wall contacts have happened</source>
        <translation>rapporten nollställer bollen när fler golv- och väggkontakter än så har skett</translation>
    </message>
    <message>
        <source>the tangent</source>
        <translation>tangenten</translation>
    </message>
    <message>
        <source>two balls collide when their centres are closer than c r</source>
        <translation>två bollar kolliderar när deras centrum är närmare än c r</translation>
    </message>
    <message>
        <source>unit</source>
        <translation>enhet</translation>
    </message>
    <message>
        <source>unit/frame^2</source>
        <translation>enhet/bildruta^2</translation>
    </message>
    <message>
        <source>unit/step</source>
        <translation>enhet/steg</translation>
    </message>
    <message>
        <source>unit/step^2</source>
        <translation>enhet/steg^2</translation>
    </message>
    <message>
        <source>v_rest = sqrt(2 g h_rest)</source>
        <translation>v_rest = sqrt(2 g h_rest)</translation>
    </message>
    <message>
        <source>y: gravity, Euler step</source>
        <translation>y: gravitation, Euler-steg</translation>
    </message>
    <message>
        <source>y: moves with the new velocity (semi-implicit)</source>
        <translation>y: flyttas med den nya hastigheten (semi-implicit)</translation>
    </message>
    <message>
        <source>z of a fixed tangent with x = y = 0.3</source>
        <translation>z för en fast tangent med x = y = 0.3</translation>
    </message>
    <message>
        <source>Stage 1 as in the report: a ball bouncing on a floor</source>
        <translation>Etapp 1 som i rapporten: en boll som studsar mot ett golv</translation>
    </message>
    <message>
        <source>The report&apos;s stage 1 (section 2.2.1, Appendix A, Figure 2.5): a ball dropped from height 2000 with gravity 0.0982 per step^2, 2000 steps of dt = 1. Each bounce reverses the velocity and keeps k = 0.6 of it (eq 2.3); once more than 10 bounces have happened, the report&apos;s counter stops the ball.</source>
        <translation>Rapportens etapp 1 (avsnitt 2.2.1, bilaga A, figur 2.5): en boll som släpps från höjden 2000 med tyngdaccelerationen 0.0982 per steg^2, 2000 steg med dt = 1. Varje studs vänder hastigheten och behåller andelen k = 0.6 av den (ekv. 2.3); när fler än 10 studsar har skett stoppar rapportens räknare bollen.</translation>
    </message>
    <message>
        <source>Zeno: infinitely many bounces in a finite time (k = 0.9)</source>
        <translation>Zeno: oändligt många studsar på ändlig tid (k = 0.9)</translation>
    </message>
    <message>
        <source>Textbook physics with k = 0.9: every bounce keeps 90 % of the speed, so every flight lasts 0.9 of the one before. The flight times form a geometric series, and infinitely many bounces fit into t = t0 (1 + k) / (1 - k) = 19 t0, about 3835 steps, where t0 = 201.8 steps is the first fall from height 2000. The event-driven integrator solves every impact time exactly; the report instead stops the ball after 10 bounces.</source>
        <translation>Läroboksfysik med k = 0.9: varje studs behåller 90 % av farten, så varje flykt varar 0.9 av den föregående. Flygtiderna bildar en geometrisk serie, och oändligt många studsar ryms inom t = t0 (1 + k) / (1 - k) = 19 t0, ungefär 3835 steg, där t0 = 201.8 steg är det första fallet från höjden 2000. Den händelsestyrda integratorn löser varje stöttidpunkt exakt; rapporten stoppar i stället bollen efter 10 studsar.</translation>
    </message>
    <message>
        <source>Stage 2 as in the report: one ball in a box</source>
        <translation>Etapp 2 som i rapporten: en boll i en kub</translation>
    </message>
    <message>
        <source>The report&apos;s stage 2 (section 2.2.2, Figures 2.6 and 2.7): a ball thrown from (2, 20, 2) m at (10, 0, 15) m/s inside an open-top box of side 300 m, g = 9.82 m/s^2, 6000 steps of 0.01 s. Floor and walls reverse the velocity along their axis and keep k = 0.9 of it (eq 2.17); after more than 50 contacts the report&apos;s counter stops the ball.</source>
        <translation>Rapportens etapp 2 (avsnitt 2.2.2, figur 2.6 och 2.7): en boll som kastas från (2, 20, 2) m med (10, 0, 15) m/s i en kub utan tak med sidan 300 m, g = 9.82 m/s^2, 6000 steg om 0.01 s. Golv och väggar vänder hastigheten längs sin axel och behåller andelen k = 0.9 av den (ekv. 2.17); efter fler än 50 kontakter stoppar rapportens räknare bollen.</translation>
    </message>
    <message>
        <source>Stage 4 with the 200 balls of Figure 3.1</source>
        <translation>Etapp 4 med de 200 bollarna i figur 3.1</translation>
    </message>
    <message>
        <source>The report&apos;s WebGL model with the 200 balls its Figure 3.1 shows (its code starts 150). Everything else is as in the report: radius 1, a box 100 wide, one update per frame.</source>
        <translation>Rapportens WebGL-modell med de 200 bollar som dess figur 3.1 visar (dess kod startar 150). Allt annat är som i rapporten: radien 1, en kub med sidan 100, en uppdatering per bildruta.</translation>
    </message>
    <message>
        <source>Stage 4 as in the report: 150 balls in a box</source>
        <translation>Etapp 4 som i rapporten: 150 bollar i en kub</translation>
    </message>
    <message>
        <source>The report&apos;s WebGL model (section 2.3, Appendix D): 150 balls of radius 1 start in a small cube at the centre of a box 100 wide, with random velocities, and move one update per frame for 1000 frames. Walls keep 0.9 of the normal velocity; two balls closer than 2.2 r collide by eqs 2.23-2.31.</source>
        <translation>Rapportens WebGL-modell (avsnitt 2.3, bilaga D): 150 bollar med radien 1 startar i en liten kub i mitten av en kub med sidan 100, med slumpade hastigheter, och flyttas en uppdatering per bildruta i 1000 bildrutor. Väggarna behåller 0.9 av normalhastigheten; två bollar närmare än 2.2 r kolliderar enligt ekv. 2.23-2.31.</translation>
    </message>
    <message>
        <source>Head-on collision: the moving ball stops</source>
        <translation>Kollision rakt framifrån: den rörliga bollen stannar</translation>
    </message>
    <message>
        <source>Textbook physics with gravity switched off, so only the collision changes the motion. Ball 1 moves at 10 m/s along z towards ball 2, which is at rest, centre on centre; they touch at t = 9 s. The whole velocity lies along the line of centres, so with equal masses and e = 1 (eqs 2.6-2.7) ball 1 stops dead and ball 2 leaves at 10 m/s, as in Newton&apos;s cradle. Lower e and ball 1 follows at (1 - e) 5 m/s.</source>
        <translation>Läroboksfysik utan tyngdkraft, så att bara kollisionen ändrar rörelsen. Boll 1 rör sig med 10 m/s längs z mot boll 2, som ligger stilla, centrum mot centrum; de möts vid t = 9 s. Hela hastigheten ligger längs centrumlinjen, så med lika massor och e = 1 (ekv. 2.6-2.7) stannar boll 1 tvärt och boll 2 far iväg med 10 m/s, som i Newtons vagga. Sänk e så följer boll 1 efter med (1 - e) 5 m/s.</translation>
    </message>
    <message>
        <source>Oblique collision: the balls leave at right angles</source>
        <translation>Sned kollision: bollarna skiljs åt i rät vinkel</translation>
    </message>
    <message>
        <source>As the head-on collision, but ball 2 sits 5 m (one radius) to the side, so at contact the line of centres is 30 degrees off ball 1&apos;s path. Only the normal part of ball 1&apos;s velocity, 10 cos 30 = 8.66 m/s, passes to ball 2; the tangential part, 10 sin 30 = 5 m/s, stays with ball 1 (eqs 2.8-2.9). With equal masses and e = 1 the two leave at right angles, as on a billiard table.</source>
        <translation>Som kollisionen rakt framifrån, men boll 2 ligger 5 m (en radie) åt sidan, så vid kontakten pekar centrumlinjen 30 grader från boll 1:s bana. Bara normaldelen av boll 1:s hastighet, 10 cos 30 = 8.66 m/s, går över till boll 2; den tangentiella delen, 10 sin 30 = 5 m/s, stannar hos boll 1 (ekv. 2.8-2.9). Med lika massor och e = 1 skiljs de åt i rät vinkel, som på ett biljardbord.</translation>
    </message>
    <message>
        <source>Stage 3 as in the report: two balls meet head-on</source>
        <translation>Etapp 3 som i rapporten: två bollar möts rakt framifrån</translation>
    </message>
    <message>
        <source>The report&apos;s stage 3 (Appendix C): two balls of radius 1 m start at opposite walls, at (2, 20, 2) m and (2, 20, 298) m, with velocities (10, 0, 15) and (10, 0, -15) m/s, and meet along z. Instead of eqs 2.4-2.11 the report&apos;s code swaps the two velocities and scales them by 0.95; run the physical model beside it to see the difference.</source>
        <translation>Rapportens etapp 3 (bilaga C): två bollar med radien 1 m startar vid motsatta väggar, i (2, 20, 2) m och (2, 20, 298) m, med hastigheterna (10, 0, 15) och (10, 0, -15) m/s, och möts längs z. I stället för ekv. 2.4-2.11 byter rapportens kod plats på de två hastigheterna och skalar dem med 0.95; kör den fysikaliska modellen bredvid för att se skillnaden.</translation>
    </message>
    <message>
        <source>the report&apos;s own rules</source>
        <translation>rapportens egna regler</translation>
    </message>
    <message>
        <source>textbook rigid balls</source>
        <translation>stela bollar enligt läroboken</translation>
    </message>
    <message>
        <source>the report&apos;s own discrete rules, bounce counters and all (one scheme per stage)</source>
        <translation>rapportens egna diskreta regler, med studsräknare och allt (ett schema per etapp)</translation>
    </message>
    <message>
        <source>textbook rigid-ball physics: momentum-conserving impulses, a physical rest rule</source>
        <translation>läroboksfysik för stela bollar: impulser som bevarar rörelsemängden, en fysikalisk viloregel</translation>
    </message>
    <message>
        <source>Stage 1 twice: the report&apos;s rules beside textbook physics</source>
        <translation>Etapp 1 två gånger: rapportens regler bredvid läroboksfysik</translation>
    </message>
    <message>
        <source>The report&apos;s stage 1 (solid ball, full lines) beside the physical model with symplectic Euler and impacts located inside the step (ghost ball, dotted lines): the same start, the same constants, the same step of 1. The report finds each bounce only at the end of a step and stops the ball after 10 bounces; the physical model solves each impact time inside the step and lets the ball come to rest by its own rest rule. The energy chart shows where the two part, and the difference chart how far apart the two balls are (report minus physical).</source>
        <translation>Rapportens etapp 1 (hel boll, heldragna linjer) bredvid den fysikaliska modellen med symplektisk Euler och stötar lokaliserade inom steget (spökboll, prickade linjer): samma start, samma konstanter, samma steg 1. Rapporten hittar varje studs först i slutet av ett steg och stoppar bollen efter 10 studsar; den fysikaliska modellen löser varje stöttid inom steget och låter bollen komma till vila enligt sin egen viloregel. Energidiagrammet visar var de två skiljs åt, och skillnadsdiagrammet hur långt isär de två bollarna är (rapporten minus den fysikaliska).</translation>
    </message>
    <message>
        <source>Walton S10, rolling S2</source>
        <translation>Walton S10, rullning S2</translation>
    </message>
    <message>
        <source>Walton S9</source>
        <translation>Walton S9</translation>
    </message>
    <message>
        <source>I = q m r^2</source>
        <translation>I = q m r^2</translation>
    </message>
    <message>
        <source>free rotation: w constant in flight</source>
        <translation>fri rotation: w konstant under flykten</translation>
    </message>
    <message>
        <source>rad/s</source>
        <translation>rad/s</translation>
    </message>
    <message>
        <source>rad/step</source>
        <translation>rad/steg</translation>
    </message>
    <message>
        <source>Coulomb friction at every contact, walls, floor and between the balls: an impact&apos;s tangential impulse is at most mu times its normal one, and a ball sliding on the floor feels mu m g at its contact point until it rolls (0: smooth)</source>
        <translation>Coulombfriktion vid varje kontakt, väggar, golv och mellan bollarna: en stöts tangentiella impuls är högst mu gånger dess normala, och en boll som glider på golvet känner mu m g i sin kontaktpunkt tills den rullar (0: glatt)</translation>
    </message>
    <message>
        <source>Coulomb friction at floor and walls: an impact&apos;s tangential impulse is at most mu times its normal one, and a ball sliding on the floor feels mu m g at its contact point until it rolls (0: smooth)</source>
        <translation>Coulombfriktion vid golv och väggar: en stöts tangentiella impuls är högst mu gånger dess normala, och en boll som glider på golvet känner mu m g i sin kontaktpunkt tills den rullar (0: glatt)</translation>
    </message>
    <message>
        <source>tangential restitution of the contact point&apos;s sliding velocity when friction holds it: -1 smooth (no friction at all), 0 the contact point stops, 1 it reverses (a superball)</source>
        <translation>tangentiell studskoefficient för kontaktpunktens glidhastighet när friktionen håller: -1 glatt (ingen friktion alls), 0 kontaktpunkten stannar, 1 den vänder (en superboll)</translation>
    </message>
    <message>
        <source>moment of inertia as a fraction of m r^2: 2/5 a solid ball, 2/3 a hollow shell</source>
        <translation>tröghetsmoment som andel av m r^2: 2/5 en massiv boll, 2/3 ett tunt skal</translation>
    </message>
    <message>
        <source>radius of the ball: the lever arm of friction and the r of I = q m r^2 (for contact the ball is a point, as in the report)</source>
        <translation>bollens radie: friktionens hävarm och r i I = q m r^2 (för kontakt är bollen en punkt, som i rapporten)</translation>
    </message>
    <message>
        <source>start spin about the vertical axis, up positive (right-hand rule): the only spin a ball moving on one axis can have; the floor&apos;s contact point has no lever on it, so it stays</source>
        <translation>startrotation kring den lodräta axeln, uppåt positiv (högerhandsregeln): den enda rotation en boll som rör sig längs en axel kan ha; golvets kontaktpunkt har ingen hävarm på den, så den består</translation>
    </message>
    <message>
        <source>start angular velocity of the ball (x, y, z), right-hand rule</source>
        <translation>bollens vinkelhastighet vid start (x, y, z), högerhandsregeln</translation>
    </message>
    <message>
        <source>start angular velocity of ball 1 (x, y, z), right-hand rule</source>
        <translation>boll 1:s vinkelhastighet vid start (x, y, z), högerhandsregeln</translation>
    </message>
    <message>
        <source>start angular velocity of ball 2 (x, y, z), right-hand rule</source>
        <translation>boll 2:s vinkelhastighet vid start (x, y, z), högerhandsregeln</translation>
    </message>
    <message>
        <source>Late impacts: a coarse step is put back on the wall</source>
        <translation>Sena stötar: ett grovt steg sätts tillbaka på väggen</translation>
    </message>
    <message>
        <source>A fast ball (240 m/s along x) and a coarse step of 0.25 s: one step covers 60 m, a fifth of the box. Impacts are looked for only at the end of each step, as the report does: the step from x = 270 m ends at x = 330 m, 30 m beyond the wall at x = 300 m, and the impact found there puts the ball back on the wall and turns it at t = 1.25 s, where it should have turned at t = 1.125 s. The ball never shows beyond the wall, but every such impact comes up to a step late: at t = 1.25 s it is on the wall instead of 27 m back from it. Set impacts to located, or the integrator to event, and the impact time is solved inside the step. Balls that pass right through each other between two steps: see the Tunnelling preset of stage 3.</source>
        <translation>En snabb boll (240 m/s längs x) och ett grovt steg på 0.25 s: ett steg täcker 60 m, en femtedel av lådan. Stötar söks bara i slutet av varje steg, som rapporten gör: steget från x = 270 m slutar vid x = 330 m, 30 m bortom väggen vid x = 300 m, och stöten som hittas där sätter tillbaka bollen på väggen och vänder den vid t = 1.25 s, där den borde ha vänt vid t = 1.125 s. Bollen syns aldrig bortom väggen, men varje sådan stöt kommer upp till ett steg för sent: vid t = 1.25 s står den på väggen i stället för 27 m tillbaka från den. Välj lokaliserade stötar, eller den händelsestyrda integratorn, så löses stöttiden inom steget. Bollar som går rakt igenom varandra mellan två steg: se förinställningen Tunnling i etapp 3.</translation>
    </message>
    <message>
        <source>Tunnelling: two balls pass through each other between two steps</source>
        <translation>Tunnling: två bollar går igenom varandra mellan två steg</translation>
    </message>
    <message>
        <source>Two balls of radius 5 m fly head-on at 25 m/s each, gravity off, with a coarse step of 0.5 s and impacts looked for only at the end of each step. At t = 5 s their centres are 12.5 m apart, 2.5 m short of touching; one step later they are 12.5 m apart again, each on the other&apos;s side: they passed through each other inside the step, and no step end saw them overlap. The health check pauses the run there. Set impacts to located and the contact at t = 5.05 s is solved inside the step: the balls bounce back.</source>
        <translation>Två bollar med radien 5 m flyger rakt mot varandra med 25 m/s var, utan tyngdkraft, med ett grovt steg på 0.5 s och stötar som söks bara i slutet av varje steg. Vid t = 5 s är deras centrum 12.5 m från varandra, 2.5 m från att nudda; ett steg senare är de åter 12.5 m från varandra, var och en på den andras sida: de gick igenom varandra inom steget, och inget stegslut såg dem överlappa. Hälsokontrollen pausar körningen där. Välj lokaliserade stötar så löses kontakten vid t = 5.05 s inom steget: bollarna studsar tillbaka.</translation>
    </message>
    <message>
        <source>%1: %2 is not a number</source>
        <translation>%1: %2 är inget tal</translation>
    </message>
    <message>
        <source>%1: %2 is too small for a double (below 4.9e-324); write 0 or a larger value</source>
        <translation>%1: %2 är för litet för ett flyttal (under 4.9e-324); skriv 0 eller ett större värde</translation>
    </message>
    <message>
        <source>%1: %2 is too large for a double (above 1.8e308)</source>
        <translation>%1: %2 är för stort för ett flyttal (över 1.8e308)</translation>
    </message>
    <message>
        <source>%1: %2 is not a finite number</source>
        <translation>%1: %2 är inget ändligt tal</translation>
    </message>
    <message>
        <source>%1: value is not a finite number</source>
        <translation>%1: värdet är inget ändligt tal</translation>
    </message>
    <message>
        <source>%1: %2 is not a whole number</source>
        <translation>%1: %2 är inget heltal</translation>
    </message>
    <message>
        <source>%1: %2 is too large</source>
        <translation>%1: %2 är för stort</translation>
    </message>
    <message>
        <source>%1: %2 is beyond 2^53 - 1 = 9007199254740991, the largest whole number kept exactly</source>
        <translation>%1: %2 är större än 2^53 - 1 = 9007199254740991, det största heltal som lagras exakt</translation>
    </message>
    <message>
        <source>%1: %2 is not a vector x,y,z of three numbers</source>
        <translation>%1: %2 är ingen vektor x,y,z av tre tal</translation>
    </message>
    <message>
        <source>%1: %2 is not a vector x,y,z of three finite numbers</source>
        <translation>%1: %2 är ingen vektor x,y,z av tre ändliga tal</translation>
    </message>
    <message>
        <source>%1: %2 is outside the allowed range %3</source>
        <translation>%1: %2 ligger utanför det tillåtna intervallet %3</translation>
    </message>
    <message>
        <source>%1: %2 (%3 component) is outside the allowed range %4</source>
        <translation>%1: %2 (%3-komponenten) ligger utanför det tillåtna intervallet %4</translation>
    </message>
    <message>
        <source>%1: %2 lies outside the box of side %3 m (x and z must be within [0, box])</source>
        <translation>%1: %2 ligger utanför lådan med sidan %3 m (x och z måste ligga inom [0, box])</translation>
    </message>
    <message>
        <source>box: %1 leaves no room for a ball of radius %2 (box must exceed 2 r)</source>
        <translation>box: %1 lämnar ingen plats för en boll med radien %2 (box måste vara större än 2 r)</translation>
    </message>
    <message>
        <source>dt: %1 must be positive</source>
        <translation>dt: %1 måste vara positivt</translation>
    </message>
    <message>
        <source>steps: %1 is outside [1, %2]</source>
        <translation>steps: %1 ligger utanför [1, %2]</translation>
    </message>
    <message>
        <source>compare with %1: %2</source>
        <translation>jämför med %1: %2</translation>
    </message>
    <message>
        <source>compare with %1: the two runs do not start at the same time with the same balls</source>
        <translation>jämför med %1: de två körningarna startar inte vid samma tid med samma bollar</translation>
    </message>
    <message>
        <source>rad/frame</source>
        <translation>rad/bildruta</translation>
    </message>
    <message>
        <source>start spins: each component of every ball&apos;s w uniform in [-spin, spin], drawn from the seed (0: the balls start without spin)</source>
        <translation>startrotationer: varje komponent av varje bolls w likformigt fördelad i [-spin, spin], dragen ur fröet (0: bollarna startar utan rotation)</translation>
    </message>
    <message>
        <source>A sliding ball starts to roll: the 5/7 rule</source>
        <translation>En glidande boll börjar rulla: 5/7-regeln</translation>
    </message>
    <message>
        <source>A ball set down on the floor at 5 m/s without spin, on a floor with little friction (mu = 0.02). Friction at its contact point slows the ball at mu g = 0.196 m/s^2 and spins it up, until the contact point stops slipping at t* = q v0 / ((1 + q) mu g) = 7.274 s (q = 2/5, a solid ball). From then on it rolls at 5/7 of its start speed, 3.571 m/s, with r w = v, and no friction acts on it any more: the pattern on the ball turns faster until it rolls, the spin chart levels off, and the energy chart shows rotation taking its share (and sliding losing some).</source>
        <translation>En boll som sätts ned på golvet med 5 m/s utan rotation, på ett golv med lite friktion (mu = 0.02). Friktionen i kontaktpunkten bromsar bollen med mu g = 0.196 m/s^2 och sätter den i rotation, tills kontaktpunkten slutar glida vid t* = q v0 / ((1 + q) mu g) = 7.274 s (q = 2/5, en massiv boll). Därefter rullar den med 5/7 av startfarten, 3.571 m/s, med r w = v, och ingen friktion verkar längre på den: mönstret på bollen snurrar allt fortare tills den rullar, rotationsdiagrammet planar ut, och energidiagrammet visar rotationen ta sin andel (och glidningen förlora en del).</translation>
    </message>
    <message>
        <source>Back-spin: a ball that bounces backwards</source>
        <translation>Bakåtskruv: en boll som studsar bakåt</translation>
    </message>
    <message>
        <source>A ball thrown forwards at 6 m/s from 100 m up, with back-spin: w = 6.8 rad/s about z, r w = 25.5 m/s against its motion. At the floor friction grips the contact point (mu = 0.5, beta = 0: the contact point stops), and the angular momentum about it, m r n x v + I w, is kept (S13): the ball leaves at v&apos; = (v - q r w) / (1 + q) = -3 m/s, backwards, rolling with r w = 3 m/s. Without the spin it would have bounced on forwards at 5/7 of 6 m/s.</source>
        <translation>En boll som kastas framåt med 6 m/s från 100 m höjd, med bakåtskruv: w = 6.8 rad/s kring z, r w = 25.5 m/s mot rörelsen. Vid golvet griper friktionen kontaktpunkten (mu = 0.5, beta = 0: kontaktpunkten stannar), och rörelsemängdsmomentet kring den, m r n x v + I w, bevaras (S13): bollen lämnar golvet med v&apos; = (v - q r w) / (1 + q) = -3 m/s, bakåt, rullande med r w = 3 m/s. Utan skruven hade den studsat vidare framåt med 5/7 av 6 m/s.</translation>
    </message>
    <message>
        <source>A superball under a table comes back out</source>
        <translation>En superboll under ett bord kommer tillbaka ut</translation>
    </message>
    <message>
        <source>Garwin&apos;s superball (1969): with k = 1 and beta = 1 an impact that sticks reverses the contact point&apos;s slip and loses no energy. Thrown under a table, the ball bounces off the floor, then off the underside of the table, and comes back out towards the thrower. The box has no table, so gravity is off and two of its walls stand in, seen from above: the wall z = 0 (at the bottom) is the floor and z = 60 (at the top) the table&apos;s underside. The ball comes in from the left at 10 m/s without spin; the floor sends it on at 3/7 of that, 4.29 m/s, spinning with r w = 2 u / (1 + q) = 14.3 m/s (S9), and the table sends it back out to the left at 6.33 m/s. The energy stays the same to round-off.</source>
        <translation>Garwins superboll (1969): med k = 1 och beta = 1 vänder en stöt som fastnar kontaktpunktens glidning och förlorar ingen energi. Kastad in under ett bord studsar bollen mot golvet, sedan mot bordets undersida, och kommer tillbaka ut mot den som kastade. Lådan har inget bord, så tyngdkraften är avstängd och två av dess väggar får stå för dem, sedda ovanifrån: väggen z = 0 (nederst) är golvet och z = 60 (överst) bordets undersida. Bollen kommer in från vänster med 10 m/s utan rotation; golvet skickar den vidare med 3/7 av det, 4.29 m/s, roterande med r w = 2 u / (1 + q) = 14.3 m/s (S9), och bordet skickar den tillbaka ut åt vänster med 6.33 m/s. Energin förblir densamma så när som på avrundning.</translation>
    </message>
    <message>
        <source>Two balls with friction: spin passed from one ball to the other</source>
        <translation>Två bollar med friktion: rotation som förs över från den ena bollen till den andra</translation>
    </message>
    <message>
        <source>Ball 1 spins about the vertical at 4 rad/s and runs at 5 m/s into ball 2, which rests without spin; gravity is off, so nothing else touches them until the walls, 5.7 s later. At the contact friction grips (mu = 0.5, beta = 0): one tangential impulse acts on the two balls at their one contact point, in opposite directions, so their momentum is kept (they move apart sideways at 1.14 m/s each) and both spins change by the same amount in the same sense (S11-S12): ball 1 keeps 2.57 rad/s and ball 2 starts to spin at -1.43 rad/s, like a gear driven by the first. Choose ball 2 in the charts to follow its spin.</source>
        <translation>Boll 1 snurrar kring den lodräta axeln med 4 rad/s och rullar med 5 m/s in i boll 2, som ligger stilla utan rotation; tyngdkraften är avstängd, så inget annat rör dem förrän väggarna, 5.7 s senare. Vid kontakten griper friktionen (mu = 0.5, beta = 0): en enda tangentiell impuls verkar på de två bollarna i deras gemensamma kontaktpunkt, i motsatta riktningar, så rörelsemängden bevaras (de glider isär i sidled med 1.14 m/s var) och båda rotationerna ändras lika mycket åt samma håll (S11-S12): boll 1 behåller 2.57 rad/s och boll 2 börjar snurra med -1.43 rad/s, som ett kugghjul som drivs av det första. Välj boll 2 i diagrammen för att följa dess rotation.</translation>
    </message>
    <message>
        <source>&quot;The basic idea was that the balls would bounce down a street like the picture from Sony&apos;s advert; the simulation was done in a simplified environment, a box, to establish that the basic functions work.&quot; The report&apos;s rules have no slope, kerb or crossing: this stage is the physical model&apos;s.</source>
        <translation>&quot;Grundidén var att bollarna skulle studsa nedför en gata som på bilden från Sonys reklamfilm; simuleringen gjordes i en förenklad miljö, en kub, för att visa att de grundläggande funktionerna fungerar.&quot; Rapportens regler har ingen lutning, trottoarkant eller korsning: den här etappen hör till den fysikaliska modellen.</translation>
    </message>
    <message>
        <source>3.1, Figure 1</source>
        <translation>3.1, Figur 1</translation>
    </message>
    <message>
        <source>Balls down a steep street</source>
        <translation>Bollar nedför en brant gata</translation>
    </message>
    <message>
        <source>St1</source>
        <translation>St1</translation>
    </message>
    <message>
        <source>St1-St2</source>
        <translation>St1-St2</translation>
    </message>
    <message>
        <source>St4</source>
        <translation>St4</translation>
    </message>
    <message>
        <source>The report&apos;s basic idea: balls bouncing down a steep street, as in Sony&apos;s advert, set going by gravity, slope and rotation. A hopper above the top releases them; they roll, slide and jump down the blocks, over the flat crossings, between kerbs and house fronts, and leave at the foot. The report built the box to test its functions and never reached the street, so only the physical model has it.</source>
        <translation>Rapportens grundidé: bollar som studsar nedför en brant gata, som i Sonys reklamfilm, satta i rörelse av gravitation, lutning och rotation. En behållare ovanför krönet släpper dem; de rullar, glider och hoppar nedför kvarteren, över de plana korsningarna, mellan trottoarkanter och husfasader, och lämnar gatan vid dess fot. Rapporten byggde kuben för att pröva sina funktioner och nådde aldrig gatan, så bara den fysikaliska modellen har den.</translation>
    </message>
    <message>
        <source>a ball rolling without slipping down a block</source>
        <translation>en boll som rullar utan att glida nedför ett kvarter</translation>
    </message>
    <message>
        <source>a ball sliding down a block, its spin growing</source>
        <translation>en boll som glider nedför ett kvarter medan dess rotation växer</translation>
    </message>
    <message>
        <source>a ball that leaves a crossing&apos;s edge flies as a projectile</source>
        <translation>en boll som lämnar en korsnings kant flyger som en projektil</translation>
    </message>
    <message>
        <source>an impact whose rebound would rise less than this ends in contact: the ball rolls or slides on</source>
        <translation>en stöt vars studs skulle stiga mindre än så slutar i kontakt: bollen rullar eller glider vidare</translation>
    </message>
    <message>
        <source>ball radius (a superball: 3 cm)</source>
        <translation>bollens radie (en studsboll: 3 cm)</translation>
    </message>
    <message>
        <source>cars: %1 do not fit along these blocks; they hold at most %2</source>
        <translation>cars: %1 får inte plats längs de här kvarteren; de rymmer högst %2</translation>
    </message>
    <message>
        <source>cars: a roadway of %1 m is too narrow for parked cars</source>
        <translation>cars: en körbana på %1 m är för smal för parkerade bilar</translation>
    </message>
    <message>
        <source>deg</source>
        <translation>grader</translation>
    </message>
    <message>
        <source>eq 2.3, St5</source>
        <translation>ekv. 2.3, St5</translation>
    </message>
    <message>
        <source>every impact, with the street or a ball</source>
        <translation>varje stöt, mot gatan eller mot en boll</translation>
    </message>
    <message>
        <source>friction holds a ball set down on a block: it rolls (St1)</source>
        <translation>friktionen håller en boll som sätts ned på ett kvarter: den rullar (St1)</translation>
    </message>
    <message>
        <source>height of the kerbs: the sidewalks stand this far above the road</source>
        <translation>trottoarkanternas höjd: trottoarerna ligger så här högt över körbanan</translation>
    </message>
    <message>
        <source>it lands when its centre is r from the road&apos;s plane: the earliest root</source>
        <translation>den landar när dess centrum är r från körbanans plan: den tidigaste roten</translation>
    </message>
    <message>
        <source>length of a block along the road</source>
        <translation>ett kvarters längd längs gatan</translation>
    </message>
    <message>
        <source>length of each flat crossing (the top one too); the flood leaves its lower edge as projectiles</source>
        <translation>längden på varje plan korsning (även den översta); floden lämnar dess nedre kant som projektiler</translation>
    </message>
    <message>
        <source>number of balls released from the hopper above the top</source>
        <translation>antal bollar som släpps från behållaren ovanför krönet</translation>
    </message>
    <message>
        <source>parked cars (boxes) along the kerbs, spread over the blocks</source>
        <translation>parkerade bilar (lådor) längs trottoarkanterna, fördelade över kvarteren</translation>
    </message>
    <message>
        <source>restitution of every impact, with the street and between balls (a superball: 0.8-0.9)</source>
        <translation>studskoefficient för varje stöt, mot gatan och mellan bollar (en studsboll: 0,8-0,9)</translation>
    </message>
    <message>
        <source>road blocks, with a flat crossing between two</source>
        <translation>kvarter av gata, med en plan korsning mellan två</translation>
    </message>
    <message>
        <source>roadway between the kerbs</source>
        <translation>körbanan mellan trottoarkanterna</translation>
    </message>
    <message>
        <source>seed of the start positions and velocities</source>
        <translation>frö för startpositionerna och -hastigheterna</translation>
    </message>
    <message>
        <source>slope of every block (17 deg: a 31 % grade, San Francisco&apos;s steepest)</source>
        <translation>lutning för varje kvarter (17 grader: 31 % stigning, San Franciscos brantaste)</translation>
    </message>
    <message>
        <source>start velocities: each component uniform in [-speed, speed] (gravity and slope do the rest)</source>
        <translation>starthastigheter: varje komponent likformigt fördelad i [-speed, speed] (gravitation och lutning gör resten)</translation>
    </message>
    <message>
        <source>width of each sidewalk, between kerb and house fronts</source>
        <translation>bredden på varje trottoar, mellan trottoarkant och husfasader</translation>
    </message>
    <message>
        <source>width: %1 m leaves no room for balls of radius %2 m (width must be at least 8 r)</source>
        <translation>width: %1 m lämnar inget utrymme för bollar med radien %2 m (width måste vara minst 8 r)</translation>
    </message>
    <message>
        <source>10,000 superballs with restitution 0.95 and tangential restitution 0.9 (Garwin&apos;s superball: the contact point&apos;s slip reverses at each impact, so spin turns into speed and back). They keep bouncing high all the way down, jump far off each crossing, and hit the house fronts; the energy chart shows translation and rotation trading while the total falls only slowly as the balls drop.</source>
        <translation>10 000 superbollar med studskoefficienten 0.95 och den tangentiella studskoefficienten 0.9 (Garwins superboll: kontaktpunktens glidning vänds vid varje stöt, så rotation blir fart och tillbaka). De fortsätter att studsa högt hela vägen ned, hoppar långt från varje korsning och träffar husfasaderna; energidiagrammet visar translation och rotation som byter energi medan summan bara sjunker långsamt när bollarna faller.</translation>
    </message>
    <message>
        <source>One ball rolling down one block: the 5/7 rule on a slope</source>
        <translation>En boll som rullar nedför ett kvarter: 5/7-regeln i en backe</translation>
    </message>
    <message>
        <source>Sony&apos;s advert released 250,000 superballs down a San Francisco street. Here they drop from the hopper over the top of three 17 deg blocks, with restitution 0.85 and grippy rubber (mu = 0.6, beta = 0.4). Seen from the foot of the hill the flood comes down the first block within 5 s and jumps at each crossing; the speed distribution widens as the front pulls away.</source>
        <translation>Sonys reklamfilm släppte 250 000 superbollar nedför en gata i San Francisco. Här faller de från behållaren ovanför krönet av tre kvarter med 17 graders lutning, med studskoefficient 0.85 och greppigt gummi (mu = 0.6, beta = 0.4). Sedd från backens fot kommer floden nedför första kvarteret inom 5 s och hoppar vid varje korsning; fartfördelningen breddas när fronten drar ifrån.</translation>
    </message>
    <message>
        <source>Superballs: e and beta near 1</source>
        <translation>Superbollar: e och beta nära 1</translation>
    </message>
    <message>
        <source>Ten thousand superballs down a steep street</source>
        <translation>Tiotusen superbollar nedför en brant gata</translation>
    </message>
    <message>
        <source>The advert: a quarter of a million superballs</source>
        <translation>Reklamfilmen: en kvarts miljon superbollar</translation>
    </message>
    <message>
        <source>The report&apos;s basic idea (chapter 3.1): balls bouncing down a steep street like Sony&apos;s advert, set going by gravity and slope. 10,000 balls of 3 cm drop from a hopper over the top of a 17 deg street (a 31 % grade) of three 80 m blocks with flat crossings between them. They land, roll and bounce down block 1 (a rolling ball gains 5/7 g sin 17 deg = 2.05 m/s^2), jump where each crossing ends, and leave at the foot; the balls-per-second chart counts them past each block&apos;s foot.</source>
        <translation>Rapportens grundidé (kapitel 3.1): bollar som studsar nedför en brant gata som i Sonys reklamfilm, satta i rörelse av gravitation och lutning. 10 000 bollar på 3 cm faller från en behållare ovanför krönet av en gata med 17 graders lutning (31 % stigning) och tre kvarter på 80 m med plana korsningar emellan. De landar, rullar och studsar nedför kvarter 1 (en rullande boll ökar farten med 5/7 g sin 17 grader = 2.05 m/s^2), hoppar där varje korsning slutar och lämnar gatan vid foten; diagrammet med bollar per sekund räknar dem förbi varje kvarters fot.</translation>
    </message>
    <message>
        <source>One ball set down without rebound (e = 0) on a 17 deg block, 48.7 m up the road from the foot (the hopper&apos;s lowest site). Once it has landed, friction (mu = 0.5, more than q tan(theta)/(1 + q) = 0.087) keeps it rolling without slipping: it accelerates at a = g sin(theta)/(1 + q) = 5/7 x 9.82 x sin 17 deg = 2.051 m/s^2, not the 2.871 m/s^2 of a ball sliding without friction, and r w = v all the way (eq St1). The velocity chart rises in a straight line; after t = v/a = 6.9 s it reaches the foot at v = sqrt(2 a d) = sqrt(2 x 2.051 x 48.7) = 14.1 m/s and leaves the street.</source>
        <translation>En boll som sätts ned utan studs (e = 0) på ett kvarter med 17 graders lutning, 48.7 m upp längs vägen från foten (behållarens lägsta plats). När den har landat håller friktionen (mu = 0.5, mer än q tan(theta)/(1 + q) = 0.087) den rullande utan glidning: den accelererar med a = g sin(theta)/(1 + q) = 5/7 x 9.82 x sin 17 grader = 2.051 m/s^2, inte med de 2.871 m/s^2 som en boll som glider utan friktion får, och r w = v hela vägen (ekv. St1). Hastighetsdiagrammet stiger i en rät linje; efter t = v/a = 6.9 s når den foten med v = sqrt(2 a d) = sqrt(2 x 2.051 x 48.7) = 14.1 m/s och lämnar gatan.</translation>
    </message>
    <message>
        <source>&quot;Originally gravity, slope and rotation were to give the balls their initial speed and direction.&quot; Here the balls start almost at rest above the top block, each velocity component at most v_max (speed, 0.5 m/s by default): gravity and slope do the rest.</source>
        <translation>&quot;Ursprungligen skulle gravitation, lutning och rotation ge bollarna deras begynnelsehastighet och riktning.&quot; Här startar bollarna nästan i vila ovanför det översta kvarteret, varje hastighetskomponent högst v_max (speed, 0,5 m/s som standard): gravitation och lutning gör resten.</translation>
    </message>
</context>
<context>
    <name>main</name>
    <message>
        <source>--measure-frames needs the 3D view (an OpenGL platform)</source>
        <translation>--measure-frames behöver 3D-vyn (en OpenGL-plattform)</translation>
    </message>
    <message>
        <source>Bouncing and colliding balls, stage by stage.</source>
        <translation>Studsande och kolliderande bollar, etapp för etapp.</translation>
    </message>
    <message>
        <source>Start on stage KEY.</source>
        <translation>Börja på etappen KEY.</translation>
    </message>
    <message>
        <source>Set a constant, NAME=VALUE.</source>
        <translation>Sätt en konstant, NAME=VALUE.</translation>
    </message>
    <message>
        <source>Start playing.</source>
        <translation>Börja spela.</translation>
    </message>
    <message>
        <source>Play at X times real time (0.1 to 10).</source>
        <translation>Spela med X gånger verklig tid (0.1 till 10).</translation>
    </message>
    <message>
        <source>Play for S seconds, print frame times, quit.</source>
        <translation>Spela i S sekunder, skriv ut bildtider, avsluta.</translation>
    </message>
    <message>
        <source>--scene: unknown scene &apos;%1&apos;</source>
        <translation>--scene: okänd etapp &apos;%1&apos;</translation>
    </message>
    <message>
        <source>--set: the values were refused (see the window&apos;s status bar)</source>
        <translation>--set: värdena avvisades (se fönstrets statusrad)</translation>
    </message>
    <message>
        <source>--speed: %1 is outside [0.1, 10]</source>
        <translation>--speed: %1 ligger utanför [0.1, 10]</translation>
    </message>
    <message>
        <source>Open in lecture mode: full screen, large text, the step-by-step walk.</source>
        <translation>Öppna i föreläsningsläge: helskärm, stor text, genomgången steg för steg.</translation>
    </message>
    <message>
        <source>Colours: light, dark, high-contrast-light or high-contrast-dark.</source>
        <translation>Färger: light, dark, high-contrast-light eller high-contrast-dark.</translation>
    </message>
    <message>
        <source>--theme: unknown theme &apos;%1&apos;</source>
        <translation>--theme: okänt tema &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Open a built-in preset by NAME, or a preset FILE.</source>
        <translation>Öppna en inbyggd förinställning med namnet NAME eller en förinställningsfil FILE.</translation>
    </message>
    <message>
        <source>Start as on a first start: neither read nor write the remembered window, stage and settings.</source>
        <translation>Starta som första gången: läs eller skriv varken det sparade fönstret, etappen eller inställningarna.</translation>
    </message>
    <message>
        <source>A preset file to open.</source>
        <translation>En förinställningsfil att öppna.</translation>
    </message>
    <message>
        <source>a remembered setup was skipped:</source>
        <translation>en sparad uppsättning hoppades över:</translation>
    </message>
    <message>
        <source>give one preset: a FILE.json or --preset NAME|FILE</source>
        <translation>ange en förinställning: en FILE.json eller --preset NAME|FILE</translation>
    </message>
    <message>
        <source>--scene: a preset names its own stage; give one or the other</source>
        <translation>--scene: en förinställning anger sin egen etapp; ange det ena eller det andra</translation>
    </message>
    <message>
        <source>&apos;%1&apos; has more than MODEL:INTEGRATOR:IMPACTS</source>
        <translation>&apos;%1&apos; har mer än MODEL:INTEGRATOR:IMPACTS</translation>
    </message>
    <message>
        <source>unknown model &apos;%1&apos;</source>
        <translation>okänd modell &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown integrator &apos;%1&apos;</source>
        <translation>okänd integrator &apos;%1&apos;</translation>
    </message>
    <message>
        <source>unknown impact mode &apos;%1&apos;</source>
        <translation>okänt stötläge &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Run the stage again beside the first, computed by MODEL (report or physical), INTEGRATOR and IMPACTS (located or step-end).</source>
        <translation>Kör etappen en gång till bredvid den första, beräknad med MODEL (report eller physical), INTEGRATOR och IMPACTS (located eller step-end).</translation>
    </message>
    <message>
        <source>--compare: refused: %1</source>
        <translation>--compare: avvisades: %1</translation>
    </message>
    <message>
        <source>--measure-frames: %1 is outside [1, 3600] seconds</source>
        <translation>--measure-frames: %1 ligger utanför [1, 3600] sekunder</translation>
    </message>
    <message>
        <source> (did you mean %1?)</source>
        <translation> (menade du %1?)</translation>
    </message>
    <message>
        <source> (man amazeballs lists them)</source>
        <translation> (man amazeballs listar dem)</translation>
    </message>
    <message>
        <source>--set: unknown parameter &apos;%1&apos; for %2</source>
        <translation>--set: okänd parameter &apos;%1&apos; för %2</translation>
    </message>
    <message>
        <source>--set: no stage has a parameter &apos;%1&apos;</source>
        <translation>--set: ingen etapp har en parameter &apos;%1&apos;</translation>
    </message>
    <message>
        <source>Step the physical model&apos;s many balls on N threads (1 to 256; by default one fewer than the processor&apos;s cores, at most 8).</source>
        <translation>Stega den fysikaliska modellens många bollar på N trådar (1 till 256; som standard en färre än processorns kärnor, högst 8).</translation>
    </message>
    <message>
        <source>--threads: %1 is outside [1, %2]</source>
        <translation>--threads: %1 ligger utanför [1, %2]</translation>
    </message>
</context>
</TS>
