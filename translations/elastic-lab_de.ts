<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="de">
<context>
    <name>FailureText</name>
    <message>
        <source>the inner layer</source>
        <translation>die innere Schicht</translation>
    </message>
    <message>
        <source>the outer layer</source>
        <translation>die äußere Schicht</translation>
    </message>
    <message>
        <source>the layer</source>
        <translation>die Schicht</translation>
    </message>
    <message>
        <source>%1 turned inside out (its area is %2, rest %3)</source>
        <translation>%1 hat sich umgestülpt (ihre Fläche ist %2, in Ruhe %3)</translation>
    </message>
    <message>
        <source>%1 turned inside out (its volume is %2, rest %3)</source>
        <translation>%1 hat sich umgestülpt (ihr Volumen ist %2, in Ruhe %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its area is %2, rest %3)</source>
        <translation>%1 ist kollabiert (ihre Fläche ist %2, in Ruhe %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its volume is %2, rest %3)</source>
        <translation>%1 ist kollabiert (ihr Volumen ist %2, in Ruhe %3)</translation>
    </message>
    <message>
        <source>body %1: %2</source>
        <translation>Körper %1: %2</translation>
    </message>
    <message>
        <source>the state became non-finite (NaN or infinity): the step is far too large for these forces</source>
        <translation>der Zustand ist nicht mehr endlich (NaN oder unendlich): der Schritt ist für diese Kräfte viel zu groß</translation>
    </message>
    <message>
        <source>rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too stiff or singular)</source>
        <translation>rk45: die Schrittweite fiel unter die kleinste Schrittweite; die Toleranz ist nicht einzuhalten (das System ist zu steif oder singulär)</translation>
    </message>
    <message>
        <source>implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is not positive definite at this step (the body is too deformed or the step too large)</source>
        <translation>implicit-euler: das lineare Gleichungssystem (konjugierte Gradienten) konvergierte nicht; das linearisierte System ist in diesem Schritt nicht positiv definit (der Körper ist zu stark verformt oder der Schritt zu groß)</translation>
    </message>
    <message>
        <source>runaway velocity: a particle moves %1 m/s, farther than the whole box in one step</source>
        <translation>davonlaufende Geschwindigkeit: ein Teilchen bewegt sich mit %1 m/s, weiter als die ganze Box in einem Schritt</translation>
    </message>
    <message>
        <source>runaway energy: kinetic + elastic energy %1 J exceeds %2 J (%3 × the body&apos;s energy scale)</source>
        <translation>davonlaufende Energie: kinetische + elastische Energie %1 J übersteigt %2 J (%3 × die Energieskala des Körpers)</translation>
    </message>
    <message>
        <source>the state is no longer finite (particle %1)</source>
        <translation>der Zustand ist nicht mehr endlich (Teilchen %1)</translation>
    </message>
    <message>
        <source>particle %1 reached a wall: the float path has no contact (use precision double)</source>
        <translation>Teilchen %1 erreichte eine Wand: die float-Rechnung hat keinen Kontakt (wählen Sie die Genauigkeit double)</translation>
    </message>
    <message>
        <source>body %1&apos;s outer layer passed through itself in a step of %2 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>die äußere Schicht von Körper %1 ging in einem Schritt von %2 s durch sich selbst: der Schritt ist für diesen Stoß zu groß (ein kleineres dt, oder ein adaptiver Integrator, der einen solchen Schritt halbiert)</translation>
    </message>
    <message>
        <source>bodies %1 and %2 intersect (their outer layers crossed) in a step of %3 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>die Körper %1 und %2 durchdringen sich (ihre äußeren Schichten haben sich gekreuzt) in einem Schritt von %3 s: der Schritt ist für diesen Stoß zu groß (ein kleineres dt, oder ein adaptiver Integrator, der einen solchen Schritt halbiert)</translation>
    </message>
    <message>
        <source>exact spectrum, %1 eigenvalues</source>
        <translation>exaktes Spektrum, %1 Eigenwerte</translation>
    </message>
    <message>
        <source>Arnoldi, %1 Ritz values of %2</source>
        <translation>Arnoldi, %1 Ritz-Werte von %2</translation>
    </message>
    <message>
        <source>exact step matrix</source>
        <translation>exakte Schrittmatrix</translation>
    </message>
    <message>
        <source>modes of M^-1 K</source>
        <translation>Moden von M^-1 K</translation>
    </message>
    <message>
        <source>%1 chooses its own step: no DT limit from stability</source>
        <translation>%1 wählt seinen Schritt selbst: die Stabilität begrenzt DT nicht</translation>
    </message>
    <message>
        <source>%1 is stable at every DT on this body</source>
        <translation>%1 ist bei jedem DT auf diesem Körper stabil</translation>
    </message>
    <message>
        <source>%1 has no stable DT on this body: its undamped modes grow for every DT (%2)</source>
        <translation>%1 hat auf diesem Körper kein stabiles DT: seine ungedämpften Moden wachsen bei jedem DT (%2)</translation>
    </message>
    <message>
        <source>%1 is stable up to DT = %2 s on this body (%3)</source>
        <translation>%1 ist auf diesem Körper bis DT = %2 s stabil (%3)</translation>
    </message>
    <message>
        <source>%1 has no stable step on this body&apos;s undamped modes (highest w = %2 rad/s): its energy grows for every dt, here by ~%3 per second; use dt &lt;= %4 s (growth below 1 per second) or another method</source>
        <translation>%1 hat auf den ungedämpften Moden dieses Körpers keinen stabilen Schritt (höchstes w = %2 rad/s): seine Energie wächst bei jedem dt, hier um ~%3 pro Sekunde; nehmen Sie dt &lt;= %4 s (Wachstum unter 1 pro Sekunde) oder ein anderes Verfahren</translation>
    </message>
    <message>
        <source>dt = %1 s is above %2&apos;s largest stable step on this body, %3 s (linearised: %4; fastest |lambda| = %5 1/s); it will likely blow up (implicit-euler or rk45 will not)</source>
        <translation>dt = %1 s liegt über dem größten stabilen Schritt von %2 auf diesem Körper, %3 s (linearisiert: %4; schnellstes |lambda| = %5 1/s); die Rechnung wird wahrscheinlich explodieren (implicit-euler oder rk45 nicht)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>solid</source>
        <translation>durchgezogen</translation>
    </message>
    <message>
        <source>hatched</source>
        <translation>schraffiert</translation>
    </message>
    <message>
        <source>dotted</source>
        <translation>gepunktet</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>Konnte %1 nicht öffnen: %2</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>Konnte %1 nicht schreiben: %2</translation>
    </message>
    <message>
        <source>the data was not written completely</source>
        <translation>die Daten wurden nicht vollständig geschrieben</translation>
    </message>
    <message>
        <source>Could not encode %1 as %2</source>
        <translation>Konnte %1 nicht als %2 kodieren</translation>
    </message>
    <message>
        <source>No plot to export</source>
        <translation>Kein Diagramm zum Exportieren</translation>
    </message>
    <message>
        <source>Could not encode %1</source>
        <translation>Konnte %1 nicht kodieren</translation>
    </message>
    <message>
        <source>Three Verlet substeps (the middle one backwards): fourth order, and energy stays bounded like Verlet&apos;s; stable up to h·ω ≈ 1.57 on an undamped spring.</source>
        <translation>Drei Verlet-Teilschritte (der mittlere rückwärts): vierte Ordnung, und die Energie bleibt beschränkt wie bei Verlet; stabil bis h·ω ≈ 1,57 an einer ungedämpften Feder.</translation>
    </message>
    <message>
        <source>Fifteen Verlet substeps: eighth order for undamped bodies, the error reaches round-off at moderate steps; 16 force evaluations a step.</source>
        <translation>Fünfzehn Verlet-Teilschritte: achte Ordnung für ungedämpfte Körper, der Fehler erreicht schon bei mäßigen Schritten die Rundungsgrenze; 16 Kraftauswertungen pro Schritt.</translation>
    </message>
    <message>
        <source>Chooses its own step to meet a tolerance; the readout shows its error estimate.</source>
        <translation>Wählt seine Schrittweite selbst, um eine Toleranz einzuhalten; die Anzeige zeigt seine Fehlerschätzung.</translation>
    </message>
    <message>
        <source>Stable at any DT (it damps instead of blowing up): the one to use for DT 0.3.</source>
        <translation>Stabil bei jedem DT (es dämpft, statt zu explodieren): das Verfahren für DT 0,3.</translation>
    </message>
    <message>
        <source>A production stiff solver (SUNDIALS): wins where stiffness is damping (overdamped springs), not where it is fast oscillation, which it must still follow.</source>
        <translation>Ein Löser für steife Probleme aus der Praxis (SUNDIALS): stark, wo die Steifheit von Dämpfung kommt (überdämpfte Federn), nicht bei schneller Schwingung, der er trotzdem folgen muss.</translation>
    </message>
    <message>
        <source>A production non-stiff solver (SUNDIALS): high order, few force evaluations per step.</source>
        <translation>Ein Löser für nicht steife Probleme aus der Praxis (SUNDIALS): hohe Ordnung, wenige Kraftauswertungen pro Schritt.</translation>
    </message>
    <message>
        <source>The game-physics way (Jolt, PhysX): stable at DT 1/60 on stiff springs, but it removes energy the body never lost; more substeps, less loss.</source>
        <translation>Der Weg der Spielphysik (Jolt, PhysX): stabil bei DT 1/60 mit steifen Federn, entzieht aber Energie, die der Körper nie verloren hat; mehr Teilschritte, weniger Verlust.</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;A two-layer elastic body: particles joined by springs, with gas inside each closed layer. Drag the body with the mouse; change any parameter while it runs.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;Ein zweischichtiger elastischer Körper: Teilchen, durch Federn verbunden, mit Gas in jeder geschlossenen Schicht. Ziehen Sie den Körper mit der Maus; jeder Parameter lässt sich während des Laufs ändern.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;The model&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Particles&lt;/b&gt; carry mass; gravity pulls along −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Springs&lt;/b&gt; (Hooke + damping): &lt;i&gt;structural&lt;/i&gt; springs along each layer (KS, KD), &lt;i&gt;radius&lt;/i&gt; springs between paired inner and outer particles and &lt;i&gt;shear&lt;/i&gt; springs across them (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: each closed layer encloses gas with P = nRT / V, pushing outward on every edge (2D) or face (3D). V is the exact area or volume.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mouse spring&lt;/b&gt; (MKS, MKD) from the pointer to the grabbed particle.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Contact&lt;/b&gt; is a smooth force inside the equations of motion: a particle that sinks a depth d into a wall is pushed back by k d³ (contact energy k d⁴/4), damped so that one hitting at contact_speed rebounds with the restitution e, with smooth Coulomb friction, and a barrier of the same kind keeps the inner layer inside the outer one. contact = projection restores the thesis program instead, which puts a particle back and reverses its normal speed after each step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resolution&lt;/b&gt; (Scene dock): with scaling = physical the masses and spring constants hold at the scene&apos;s default mesh, and a finer mesh keeps the body&apos;s totals (layer mass, material stiffness), so it is the same body, only finer; scaling = thesis makes them per particle and per spring at every mesh. A finer body has faster modes and needs a smaller DT: the window offers one when a rebuild needs it.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;The plots show the energy book: kinetic + spring + gravity + gas + contact is the total; what damping and contact take out is &apos;removed&apos;. For an exact integrator, total + removed − work by the mouse stays constant; the readout&apos;s &lt;i&gt;energy drift&lt;/i&gt; is how far it is off.&lt;/p&gt;&lt;p&gt;View → &lt;b&gt;Energy bars&lt;/b&gt; shows the same book as bars, one per term, in the plot&apos;s colours, with the drift last. View → &lt;b&gt;P–V diagram&lt;/b&gt; shows each gas layer&apos;s pressure against its volume: the trail lies on the isotherm P = nRT / V, drawn dashed.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Das Modell&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Teilchen&lt;/b&gt; tragen Masse; die Schwerkraft zieht entlang −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Federn&lt;/b&gt; (Hooke + Dämpfung): &lt;i&gt;Strukturfedern&lt;/i&gt; entlang jeder Schicht (KS, KD), &lt;i&gt;Radialfedern&lt;/i&gt; zwischen gepaarten inneren und äußeren Teilchen und &lt;i&gt;Scherfedern&lt;/i&gt; quer dazu (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: jede geschlossene Schicht umschließt Gas mit P = nRT / V, das auf jede Kante (2D) oder Fläche (3D) nach außen drückt. V ist die exakte Fläche bzw. das exakte Volumen.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mausfeder&lt;/b&gt; (MKS, MKD) vom Zeiger zum gegriffenen Teilchen.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Kontakt&lt;/b&gt; ist eine glatte Kraft in den Bewegungsgleichungen: ein Teilchen, das um die Tiefe d in eine Wand eindringt, wird mit k d³ zurückgedrückt (Kontaktenergie k d⁴/4), so gedämpft, dass eines, das mit contact_speed aufprallt, mit der Stoßzahl e zurückspringt, mit geglätteter Coulomb-Reibung; eine Barriere derselben Art hält die innere Schicht in der äußeren. contact = projection stellt stattdessen das Programm der Diplomarbeit her, das ein Teilchen nach jedem Schritt zurücksetzt und seine Normalgeschwindigkeit umkehrt.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Auflösung&lt;/b&gt; (Szene-Dock): mit scaling = physical gelten Massen und Federkonstanten beim Standardnetz der Szene, und ein feineres Netz behält die Gesamtgrößen des Körpers (Schichtmasse, Materialsteifigkeit): es ist derselbe Körper, nur feiner; scaling = thesis macht sie bei jedem Netz zu Werten pro Teilchen und pro Feder. Ein feinerer Körper hat schnellere Moden und braucht ein kleineres DT: das Fenster bietet eines an, wenn ein Neuaufbau es verlangt.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Die Diagramme zeigen die Energiebilanz: kinetisch + Feder + Lage + Gas + Kontakt ist die Gesamtenergie; was Dämpfung und Kontakt entziehen, heißt ‚entzogen‘. Für einen exakten Integrator bleibt Gesamt + entzogen − Arbeit der Maus konstant; die &lt;i&gt;Energiedrift&lt;/i&gt; der Anzeige sagt, wie weit sie davon abweicht.&lt;/p&gt;&lt;p&gt;Ansicht → &lt;b&gt;Energiebalken&lt;/b&gt; zeigt dieselbe Bilanz als Balken, einen pro Term, in den Farben der Diagramme, die Drift zuletzt. Ansicht → &lt;b&gt;P–V-Diagramm&lt;/b&gt; zeigt den Druck jeder Gasschicht gegen ihr Volumen: die Spur liegt auf der Isotherme P = nRT / V, gestrichelt gezeichnet.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Integrators&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;name&lt;/th&gt;&lt;th&gt;order&lt;/th&gt;&lt;th&gt;what it does&lt;/th&gt;&lt;th&gt;in class&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;h3&gt;Integratoren&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;Name&lt;/th&gt;&lt;th&gt;Ordnung&lt;/th&gt;&lt;th&gt;was er tut&lt;/th&gt;&lt;th&gt;im Unterricht&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Presets&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Voreinstellungen&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Mouse&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Left-drag on the body: grab the nearest outer particle and pull it.&lt;/li&gt;&lt;li&gt;Left-drag elsewhere, or Shift+left-drag (3D): orbit. Right- or middle-drag: pan. Wheel: zoom. View → Reset view.&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Maus&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Linksziehen auf dem Körper: das nächste äußere Teilchen greifen und daran ziehen.&lt;/li&gt;&lt;li&gt;Linksziehen anderswo oder Umschalt+Linksziehen (3D): drehen. Rechts- oder Mittelziehen: verschieben. Mausrad: zoomen. Ansicht → Ansicht zurücksetzen.&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;More&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Mehr&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>The GUI (docs/gui.md)</source>
        <translation>Die Oberfläche (docs/gui.md)</translation>
    </message>
    <message>
        <source>Architecture (docs/architecture.md)</source>
        <translation>Architektur (docs/architecture.md)</translation>
    </message>
    <message>
        <source>README</source>
        <translation>README</translation>
    </message>
    <message>
        <source>1. How large may DT be for Euler?</source>
        <translation>1. Wie groß darf DT für Euler sein?</translation>
    </message>
    <message>
        <source>2. Energy drift: Euler, midpoint, RK4</source>
        <translation>2. Energiedrift: Euler, Mittelpunkt, RK4</translation>
    </message>
    <message>
        <source>3. A heavy inner layer: liquid motion</source>
        <translation>3. Eine schwere innere Schicht: Flüssigkeitsbewegung</translation>
    </message>
    <message>
        <source>4. A finer sphere needs a smaller DT</source>
        <translation>4. Eine feinere Kugel braucht ein kleineres DT</translation>
    </message>
    <message>
        <source>5. Pressure and volume on the isotherm</source>
        <translation>5. Druck und Volumen auf der Isotherme</translation>
    </message>
    <message>
        <source>6. Restitution: a particle and a body</source>
        <translation>6. Stoßzahl: ein Teilchen und ein Körper</translation>
    </message>
    <message>
        <source>7. Stiff springs: explicit against implicit</source>
        <translation>7. Steife Federn: explizit gegen implizit</translation>
    </message>
    <message>
        <source>8. Why symplectic? Energy over ten thousand periods</source>
        <translation>8. Warum symplektisch? Energie über zehntausend Perioden</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>Ziel</translation>
    </message>
    <message>
        <source>What to do</source>
        <translation>Was zu tun ist</translation>
    </message>
    <message>
        <source>What to look at</source>
        <translation>Worauf zu achten ist</translation>
    </message>
    <message>
        <source>The measured answer</source>
        <translation>Die gemessene Antwort</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Warum</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>Gas</source>
        <translation>Gas</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Umgebung</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>Mouse spring</source>
        <translation>Mausfeder</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Form</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>gas nRT</source>
        <translation>Gas nRT</translation>
    </message>
    <message>
        <source>gas nRT inner</source>
        <translation>Gas nRT innen</translation>
    </message>
    <message>
        <source>gas nRT outer</source>
        <translation>Gas nRT außen</translation>
    </message>
    <message>
        <source>Area per layer</source>
        <translation>Fläche je Schicht</translation>
    </message>
    <message>
        <source>Volume per layer</source>
        <translation>Volumen je Schicht</translation>
    </message>
    <message>
        <source>area [m²]</source>
        <translation>Fläche [m²]</translation>
    </message>
    <message>
        <source>volume [m³]</source>
        <translation>Volumen [m³]</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>innen</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>außen</translation>
    </message>
    <message>
        <source>Pressure per layer</source>
        <translation>Druck je Schicht</translation>
    </message>
    <message>
        <source>pressure [N/m]</source>
        <translation>Druck [N/m]</translation>
    </message>
    <message>
        <source>pressure [Pa]</source>
        <translation>Druck [Pa]</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energie</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>Energie [J]</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>kinetisch</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>Feder</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>Lage</translation>
    </message>
    <message>
        <source>gas</source>
        <translation>Gas</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>Kontakt</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>entzogen</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>durch Kontakt entzogen</translation>
    </message>
    <message>
        <source>spring: structural</source>
        <translation>Feder: Struktur</translation>
    </message>
    <message>
        <source>spring: radius</source>
        <translation>Feder: Radial</translation>
    </message>
    <message>
        <source>spring: shear</source>
        <translation>Feder: Scherung</translation>
    </message>
    <message>
        <source>mouse spring</source>
        <translation>Mausfeder</translation>
    </message>
    <message>
        <source>removed by damping</source>
        <translation>durch Dämpfung entzogen</translation>
    </message>
    <message>
        <source>removed by projection</source>
        <translation>durch Projektion entzogen</translation>
    </message>
    <message>
        <source>drift (balance error)</source>
        <translation>Drift (Bilanzfehler)</translation>
    </message>
    <message>
        <source>1D drop: two masses on a spring</source>
        <translation>1D-Fall: zwei Massen an einer Feder</translation>
    </message>
    <message>
        <source>Both masses fall, hit the floor and bounce; the spring oscillates (thesis fig. 7).</source>
        <translation>Beide Massen fallen, treffen auf den Boden und springen zurück; die Feder schwingt (Diplomarbeit Abb. 7).</translation>
    </message>
    <message>
        <source>1D hanging spring</source>
        <translation>1D-hängende Feder</translation>
    </message>
    <message>
        <source>The top mass is fixed; the lower one oscillates around the stretched rest length.</source>
        <translation>Die obere Masse ist fest; die untere schwingt um die gedehnte Ruhelänge.</translation>
    </message>
    <message>
        <source>2D ring</source>
        <translation>2D-Ring</translation>
    </message>
    <message>
        <source>Two gas-filled rings joined by radius and shear springs drop onto the floor (thesis 3.4).</source>
        <translation>Zwei gasgefüllte Ringe, durch Radial- und Scherfedern verbunden, fallen auf den Boden (Diplomarbeit 3.4).</translation>
    </message>
    <message>
        <source>3D sphere</source>
        <translation>3D-Kugel</translation>
    </message>
    <message>
        <source>Two gas-filled spheres (subdivided octahedron) drop and bounce (thesis 3.5.2).</source>
        <translation>Zwei gasgefüllte Kugeln (unterteiltes Oktaeder) fallen und springen (Diplomarbeit 3.5.2).</translation>
    </message>
    <message>
        <source>3D lat/long sphere (non-uniform)</source>
        <translation>3D-Längen-/Breitenkugel (ungleichmäßig)</translation>
    </message>
    <message>
        <source>The lat/long sphere: particles crowd at the poles, so the body is not uniform (thesis 3.5.1).</source>
        <translation>Die Längen-/Breitenkugel: die Teilchen drängen sich an den Polen, der Körper ist also nicht gleichmäßig (Diplomarbeit 3.5.1).</translation>
    </message>
    <message>
        <source>Heavy inner layer (non-uniform density)</source>
        <translation>Schwere innere Schicht (ungleichmäßige Dichte)</translation>
    </message>
    <message>
        <source>The inner layer is five times heavier: it sinks inside the outer one and the body lands bottom-heavy (thesis 8.1).</source>
        <translation>Die innere Schicht ist fünfmal schwerer: sie sinkt in der äußeren ab, und der Körper landet mit dem Schwerpunkt unten (Diplomarbeit 8.1).</translation>
    </message>
    <message>
        <source>Liquid motion and inertia</source>
        <translation>Flüssigkeitsbewegung und Trägheit</translation>
    </message>
    <message>
        <source>Inner and outer layers pushed in opposite directions (3 m/s), without gravity and with soft, lightly damped radius and shear springs: the inner layer sloshes inside the outer one like a liquid (thesis fig. 47).</source>
        <translation>Innere und äußere Schicht werden in entgegengesetzte Richtungen gestoßen (3 m/s), ohne Schwerkraft und mit weichen, schwach gedämpften Radial- und Scherfedern: die innere Schicht schwappt in der äußeren wie eine Flüssigkeit (Diplomarbeit Abb. 47).</translation>
    </message>
    <message>
        <source>Stability experiment, DT = %1 s</source>
        <translation>Stabilitätsexperiment, DT = %1 s</translation>
    </message>
    <message>
        <source>Euler, midpoint and RK4 from the same start at DT = %1 s (thesis 7.2.2, figs. 41-43). Watch which one blows up.</source>
        <translation>Euler, Mittelpunkt und RK4 vom selben Start bei DT = %1 s (Diplomarbeit 7.2.2, Abb. 41-43). Beobachten Sie, welches explodiert.</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>unbegrenzt</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>Cheapest and least stable: on an undamped spring it gains energy at every DT. On the two-layer ring it holds for 2 s up to DT %1 s (measured).</source>
        <translation>Am billigsten und am wenigsten stabil: an einer ungedämpften Feder gewinnt es bei jedem DT Energie. Am zweischichtigen Ring hält es 2 s lang bis DT %1 s (gemessen).</translation>
    </message>
    <message>
        <source>Two force evaluations per step, second order; on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03.</source>
        <translation>Zwei Kraftauswertungen pro Schritt, zweite Ordnung; am zweischichtigen Ring hält es 2 s lang bis DT %1 s (gemessen), scheitert also an den 0,03 der Diplomarbeit.</translation>
    </message>
    <message>
        <source>Four evaluations, fourth order; stable up to h·ω ≈ 2.8: on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03 and 0.3.</source>
        <translation>Vier Auswertungen, vierte Ordnung; stabil bis h·ω ≈ 2,8: am zweischichtigen Ring hält es 2 s lang bis DT %1 s (gemessen), scheitert also an den 0,03 und 0,3 der Diplomarbeit.</translation>
    </message>
    <message>
        <source>Same cost as Euler, but energy stays bounded on an undamped spring (h·ω &amp;lt; 2).</source>
        <translation>Gleicher Aufwand wie Euler, aber die Energie bleibt an einer ungedämpften Feder beschränkt (h·ω &amp;lt; 2).</translation>
    </message>
    <message>
        <source>Velocity Verlet: time-reversible, good long-run energy behaviour. Second order without damping; with the dampers on (every scene here) its damping sees the half-step velocity and it is first order: the fitted order on the damped spring is %1 (measured).</source>
        <translation>Geschwindigkeits-Verlet: zeitumkehrbar, gutes Energieverhalten über lange Zeit. Zweite Ordnung ohne Dämpfung; mit eingeschalteten Dämpfern (in jeder Szene hier) sieht seine Dämpfung die Geschwindigkeit im halben Schritt, und es ist von erster Ordnung: die angepasste Ordnung an der gedämpften Feder ist %1 (gemessen).</translation>
    </message>
    <message>
        <source>2 (1 damped)</source>
        <translation>2 (1 gedämpft)</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Lessons&lt;/b&gt; menu (or Help → Experiments): %1 guided experiments, each set up in one click, with what to change, what to look at and the answer measured with elastic-lab-cli; the Lesson dock shows what each answer expects beside what your run gives.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Menü &lt;b&gt;Lektionen&lt;/b&gt; (oder Hilfe → Experimente): %1 angeleitete Experimente, jedes mit einem Klick eingerichtet, mit dem, was man ändern und worauf man achten soll, und der mit elastic-lab-cli gemessenen Antwort; das Lektion-Dock zeigt neben jeder erwarteten Antwort, was Ihr Lauf ergibt.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Lessons &gt; Lesson texts explains what to do.</source>
        <translation>Lektionen &gt; Lektionstexte erklärt, was zu tun ist.</translation>
    </message>
    <message>
        <source>height of particle %1</source>
        <translation>Höhe von Teilchen %1</translation>
    </message>
    <message>
        <source>speed of particle %1</source>
        <translation>Geschwindigkeit von Teilchen %1</translation>
    </message>
    <message>
        <source>height of the inner layer&apos;s centre</source>
        <translation>Höhe des Mittelpunkts der inneren Schicht</translation>
    </message>
    <message>
        <source>height of the outer layer&apos;s centre</source>
        <translation>Höhe des Mittelpunkts der äußeren Schicht</translation>
    </message>
    <message>
        <source>centre-of-mass height</source>
        <translation>Höhe des Schwerpunkts</translation>
    </message>
    <message>
        <source>centre-of-mass speed</source>
        <translation>Geschwindigkeit des Schwerpunkts</translation>
    </message>
    <message>
        <source>layers&apos; separation</source>
        <translation>Abstand der Schichten</translation>
    </message>
    <message>
        <source>9. Two balloons collide: momentum and energy</source>
        <translation>9. Zwei Ballons stoßen zusammen: Impuls und Energie</translation>
    </message>
    <message>
        <source>10. A soft stack: how the bottom body carries the others</source>
        <translation>10. Ein weicher Stapel: wie der unterste Körper die anderen trägt</translation>
    </message>
</context>
<context>
    <name>WorldExport</name>
    <message>
        <source>No run of several bodies to export</source>
        <translation>Kein Lauf mit mehreren Körpern zum Exportieren</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Daten exportieren</translation>
    </message>
    <message>
        <source>CSV of several bodies, comma and decimal point (*.csv)</source>
        <translation>CSV mehrerer Körper, Komma und Dezimalpunkt (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %1 rows of the world to %2</source>
        <translation>%1 Zeilen der Welt nach %2 geschrieben</translation>
    </message>
</context>
<context>
    <name>elui::BodiesDock</name>
    <message>
        <source>Bodies</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>The bodies of the scene, total momentum and the smallest gap, with their curves against simulated time</source>
        <translation>Die Körper der Szene, Gesamtimpuls und kleinster Abstand, mit ihren Kurven über der simulierten Zeit</translation>
    </message>
    <message>
        <source>This dock is for scenes of several bodies: Presets &gt; Several bodies, or a scene file of several bodies.</source>
        <translation>Dieses Dock ist für Szenen mit mehreren Körpern: Voreinstellungen &gt; Mehrere Körper, oder eine Szenendatei mit mehreren Körpern.</translation>
    </message>
    <message>
        <source>body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>mass [kg]</source>
        <translation>Masse [kg]</translation>
    </message>
    <message>
        <source>centre [m]</source>
        <translation>Mittelpunkt [m]</translation>
    </message>
    <message>
        <source>velocity [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
    <message>
        <source>volume in/out</source>
        <translation>Volumen innen/außen</translation>
    </message>
    <message>
        <source>pressure in/out</source>
        <translation>Druck innen/außen</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>Gesamtimpuls</translation>
    </message>
    <message>
        <source>min_gap</source>
        <translation>min_gap</translation>
    </message>
    <message>
        <source>Volume per body and layer</source>
        <translation>Volumen je Körper und Schicht</translation>
    </message>
    <message>
        <source>Pressure per body and layer</source>
        <translation>Druck je Körper und Schicht</translation>
    </message>
    <message>
        <source>gap [m]</source>
        <translation>Abstand [m]</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>Volumen</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>Druck</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>ring2d: particles per layer; sphere3d: subdivisions; sphere3d-latlong: slices</source>
        <translation>ring2d: Teilchen je Schicht; sphere3d: Unterteilungen; sphere3d-latlong: Scheiben</translation>
    </message>
    <message>
        <source>kind, level</source>
        <translation>Art, Stufe</translation>
    </message>
    <message>
        <source>where [m]</source>
        <translation>wo [m]</translation>
    </message>
    <message>
        <source>how fast [m/s]</source>
        <translation>wie schnell [m/s]</translation>
    </message>
    <message>
        <source>Add body</source>
        <translation>Körper hinzufügen</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>Auswahl entfernen</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>innen</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>außen</translation>
    </message>
    <message>
        <source> (body%1 with itself)</source>
        <translation> (body%1 mit sich selbst)</translation>
    </message>
    <message>
        <source> (body%1 and body%2)</source>
        <translation> (body%1 und body%2)</translation>
    </message>
    <message>
        <source>beyond %1 m (nothing that close)</source>
        <translation>über %1 m (nichts so nah)</translation>
    </message>
    <message>
        <source>&lt;b&gt;momentum&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;angular momentum&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contact between bodies&lt;/b&gt; %4 J, %5 pairs in the skin</source>
        <translation>&lt;b&gt;Impuls&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;Drehimpuls&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;Kontakt zwischen Körpern&lt;/b&gt; %4 J, %5 Paare in der Hautschicht</translation>
    </message>
    <message>
        <source>%1: not a number</source>
        <translation>%1: keine Zahl</translation>
    </message>
    <message>
        <source>Choose a body in the list first.</source>
        <translation>Wählen Sie zuerst einen Körper in der Liste.</translation>
    </message>
    <message>
        <source>A world keeps at least one body.</source>
        <translation>Eine Welt behält mindestens einen Körper.</translation>
    </message>
    <message>
        <source>p [kg m/s]</source>
        <translation>p [kg m/s]</translation>
    </message>
</context>
<context>
    <name>elui::CompareDialog</name>
    <message>
        <source>Side by side</source>
        <translation>Nebeneinander</translation>
    </message>
    <message>
        <source>Run the same scene with up to three integrators from the same start state. Parameter edits and mouse drags go to all of them.</source>
        <translation>Dieselbe Szene mit bis zu drei Integratoren vom selben Startzustand laufen lassen. Parameteränderungen und Ziehen mit der Maus gehen an alle.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <source>View %1</source>
        <translation>Ansicht %1</translation>
    </message>
    <message>
        <source>The integrator of the first view</source>
        <translation>Der Integrator der ersten Ansicht</translation>
    </message>
    <message>
        <source>The integrator of this view, or none</source>
        <translation>Der Integrator dieser Ansicht, oder keiner</translation>
    </message>
    <message>
        <source>%1 s, common to every view (set it in the Run dock)</source>
        <translation>%1 s, gemeinsam für alle Ansichten (im Lauf-Dock einstellen)</translation>
    </message>
    <message>
        <source>DT</source>
        <translation>DT</translation>
    </message>
    <message>
        <source>Start the views side by side from the current start state</source>
        <translation>Die Ansichten nebeneinander vom aktuellen Startzustand starten</translation>
    </message>
    <message>
        <source>Keep the views as they are</source>
        <translation>Die Ansichten lassen, wie sie sind</translation>
    </message>
</context>
<context>
    <name>elui::ConservationDialog</name>
    <message>
        <source>Long-time energy</source>
        <translation>Energie über lange Zeit</translation>
    </message>
    <message>
        <source>Run length in periods of the body&apos;s fastest mode (damping switched off)</source>
        <translation>Laufzeit in Perioden der schnellsten Mode des Körpers (Dämpfung ausgeschaltet)</translation>
    </message>
    <message>
        <source>The fixed step of every run [s]</source>
        <translation>Die feste Schrittweite jedes Laufs [s]</translation>
    </message>
    <message>
        <source>float: the float build of the 1D spring, where round-off shows as a random walk</source>
        <translation>float: der float-Build der 1D-Feder, in dem sich Rundungsfehler als Irrfahrt zeigen</translation>
    </message>
    <message>
        <source>Periods</source>
        <translation>Perioden</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|energy error| envelope [J]</source>
        <translation>Einhüllende von |Energiefehler| [J]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation>95-%-Intervall</translation>
    </message>
    <message>
        <source>class</source>
        <translation>Klasse</translation>
    </message>
    <message>
        <source>final |ΔE| [J]</source>
        <translation>|ΔE| am Ende [J]</translation>
    </message>
    <message>
        <source>relative</source>
        <translation>relativ</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>%1: %2, α = %3</source>
        <translation>%1: %2, α = %3</translation>
    </message>
    <message>
        <source>%1: failed</source>
        <translation>%1: gescheitert</translation>
    </message>
    <message>
        <source>slope 1/2 (random walk)</source>
        <translation>Steigung 1/2 (Irrfahrt)</translation>
    </message>
    <message>
        <source>slope 1 (drift)</source>
        <translation>Steigung 1 (Drift)</translation>
    </message>
    <message>
        <source>The study did not run: %1</source>
        <translation>Die Studie lief nicht: %1</translation>
    </message>
    <message>
        <source>Undamped (%1). Fastest mode ω = %2 rad/s, period %3 s; DT = %4 s (h·ω = %5); %6 periods = %7 s. α: slope of log |ΔE| against log t from 10 periods on; bounded &lt; 0.25 ≤ random walk &lt; 0.75 ≤ drift.</source>
        <translation>Ungedämpft (%1). Schnellste Mode ω = %2 rad/s, Periode %3 s; DT = %4 s (h·ω = %5); %6 Perioden = %7 s. α: Steigung von log |ΔE| gegen log t ab 10 Perioden; beschränkt &lt; 0,25 ≤ Irrfahrt &lt; 0,75 ≤ Drift.</translation>
    </message>
</context>
<context>
    <name>elui::EnergyBarsDock</name>
    <message>
        <source>Energy bars</source>
        <translation>Energiebalken</translation>
    </message>
    <message>
        <source>Each part of the energy as a bar, named on the axis; the values are in the Run dock&apos;s readout</source>
        <translation>Jeder Teil der Energie als Balken, auf der Achse benannt; die Werte stehen in der Anzeige des Lauf-Docks</translation>
    </message>
    <message>
        <source>Energy book</source>
        <translation>Energiebilanz</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>Energie [J]</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
total %2, at the start %3</source>
        <translation>Energie bei t = %1 s
gesamt %2, zu Beginn %3</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
%2</source>
        <translation>Energie bei t = %1 s
%2</translation>
    </message>
</context>
<context>
    <name>elui::FailureBanner</name>
    <message>
        <source>Start again from the beginning with the step that ran through the failed stretch</source>
        <translation>Von vorn beginnen mit dem Schritt, der den gescheiterten Abschnitt durchlief</translation>
    </message>
    <message>
        <source>Use implicit-euler and reset</source>
        <translation>implicit-euler verwenden und zurücksetzen</translation>
    </message>
    <message>
        <source>Start again with the implicit Euler integrator, which is stable at any time step</source>
        <translation>Von vorn beginnen mit dem impliziten Euler-Integrator, der bei jeder Schrittweite stabil ist</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Start again from the beginning with the same settings</source>
        <translation>Von vorn beginnen mit denselben Einstellungen</translation>
    </message>
    <message>
        <source>&lt;b&gt;The simulation blew up&lt;/b&gt; at t = %1 s (step %2): %3. The run is paused and shows the last good state.</source>
        <translation>&lt;b&gt;Die Simulation ist explodiert&lt;/b&gt; bei t = %1 s (Schritt %2): %3. Der Lauf ist angehalten und zeigt den letzten guten Zustand.</translation>
    </message>
    <message>
        <source>Checking whether a smaller step survives the same stretch (a re-run at a quarter of DT, in the background)…</source>
        <translation>Es wird geprüft, ob ein kleinerer Schritt denselben Abschnitt übersteht (ein neuer Lauf mit einem Viertel von DT, im Hintergrund)…</translation>
    </message>
    <message>
        <source>Try a smaller DT, a more stable integrator (rk4, or implicit-euler), softer springs or less pressure, then Reset.</source>
        <translation>Versuchen Sie ein kleineres DT, einen stabileren Integrator (rk4 oder implicit-euler), weichere Federn oder weniger Druck, dann Zurücksetzen.</translation>
    </message>
    <message>
        <source>Use DT = %1 s and reset</source>
        <translation>DT = %1 s verwenden und zurücksetzen</translation>
    </message>
    <message>
        <source>The body itself collapses — no step size will save it: run again from t = %1 s at a step of %2 s (%3), it fails at t = %4 s as well (%5). Change the body instead: lighter masses or less gravity, stiffer springs (ks, and the radial ones), more gas pressure, or more damping.</source>
        <translation>Der Körper selbst kollabiert — keine Schrittweite rettet ihn: erneut ab t = %1 s mit einem Schritt von %2 s gerechnet (%3), scheitert er ebenfalls bei t = %4 s (%5). Ändern Sie stattdessen den Körper: leichtere Massen oder weniger Schwerkraft, steifere Federn (ks und die radialen), mehr Gasdruck oder mehr Dämpfung.</translation>
    </message>
    <message>
        <source>The step was too large: run again from t = %1 s at a step of %2 s, the same stretch runs through t = %3 s. The linearised body agrees: %4.</source>
        <translation>Der Schritt war zu groß: erneut ab t = %1 s mit einem Schritt von %2 s gerechnet, läuft derselbe Abschnitt bis t = %3 s durch. Der linearisierte Körper stimmt zu: %4.</translation>
    </message>
</context>
<context>
    <name>elui::HelpDialog</name>
    <message>
        <source>Elastic Lab help</source>
        <translation>Hilfe zu Elastic Lab</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Hilfe</translation>
    </message>
    <message>
        <source>How to use Elastic Lab: the view, the docks, the integrators and the files</source>
        <translation>Wie man Elastic Lab benutzt: die Ansicht, die Docks, die Integratoren und die Dateien</translation>
    </message>
    <message>
        <source>Close the help</source>
        <translation>Die Hilfe schließen</translation>
    </message>
</context>
<context>
    <name>elui::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>Lektion</translation>
    </message>
    <message>
        <source>Run until t =</source>
        <translation>Laufen bis t =</translation>
    </message>
    <message>
        <source>Run as fast as possible and pause at this simulated time.</source>
        <translation>So schnell wie möglich laufen und bei dieser simulierten Zeit anhalten.</translation>
    </message>
    <message>
        <source>Simulated time between Start and Stop (the first view&apos;s clock).</source>
        <translation>Simulierte Zeit zwischen Start und Stopp (die Uhr der ersten Ansicht).</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Start</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Null</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>Antwort</translation>
    </message>
    <message>
        <source>expected</source>
        <translation>erwartet</translation>
    </message>
    <message>
        <source>you got</source>
        <translation>Ihr Lauf</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Messen</translation>
    </message>
    <message>
        <source>Measure every answer on the parameters in use, as the lesson&apos;s elastic-lab-cli commands do (stability scans, weightless impacts, runs).</source>
        <translation>Jede Antwort mit den aktuellen Parametern messen, wie es die elastic-lab-cli-Befehle der Lektion tun (Stabilitätsscans, Aufpralle ohne Schwerkraft, Läufe).</translation>
    </message>
    <message>
        <source>&lt;small&gt;you got: from your run, or &lt;i&gt;measured&lt;/i&gt; (Measure); green within the text&apos;s tolerance, amber off it&lt;/small&gt;</source>
        <translation>&lt;small&gt;Ihr Lauf: aus Ihrem Lauf oder &lt;i&gt;gemessen&lt;/i&gt; (Messen); grün innerhalb der Toleranz des Texts, gelb außerhalb&lt;/small&gt;</translation>
    </message>
    <message>
        <source>No lesson: choose one in the Lessons menu. Run until and the stopwatch work for any scene.</source>
        <translation>Keine Lektion: wählen Sie eine im Menü Lektionen. „Laufen bis“ und die Stoppuhr funktionieren in jeder Szene.</translation>
    </message>
    <message>
        <source>Stopwatch: &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>Stoppuhr: &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Stopp</translation>
    </message>
    <message>
        <source>read off your run</source>
        <translation>aus Ihrem Lauf abgelesen</translation>
    </message>
    <message>
        <source>press Measure</source>
        <translation>Messen drücken</translation>
    </message>
    <message>
        <source>measured on the parameters in use</source>
        <translation>mit den aktuellen Parametern gemessen</translation>
    </message>
    <message>
        <source>t = &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>t = &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1: energy drift &lt;b&gt;%2 J&lt;/b&gt;%3</source>
        <translation>%1: Energiedrift &lt;b&gt;%2 J&lt;/b&gt;%3</translation>
    </message>
    <message>
        <source>, blew up at t = %1 s</source>
        <translation>, explodiert bei t = %1 s</translation>
    </message>
    <message>
        <source>centre of mass: %1 m above the floor, vertical speed %2 m/s</source>
        <translation>Schwerpunkt: %1 m über dem Boden, vertikale Geschwindigkeit %2 m/s</translation>
    </message>
    <message>
        <source>layer centres above the floor: inner %1 m, outer %2 m; the inner one sits &lt;b&gt;%3 m&lt;/b&gt; %4</source>
        <translation>Mittelpunkte der Schichten über dem Boden: innen %1 m, außen %2 m; die innere liegt &lt;b&gt;%3 m&lt;/b&gt; %4</translation>
    </message>
    <message>
        <source>below</source>
        <translation>darunter</translation>
    </message>
    <message>
        <source>above</source>
        <translation>darüber</translation>
    </message>
    <message>
        <source>centre of mass hit the floor at %1 m/s%2</source>
        <translation>der Schwerpunkt traf mit %1 m/s auf den Boden%2</translation>
    </message>
    <message>
        <source>, left it at %1 m/s (ratio %2)</source>
        <translation>, verließ ihn mit %1 m/s (Verhältnis %2)</translation>
    </message>
    <message>
        <source>lowest point %1 m above the floor%2</source>
        <translation>tiefster Punkt %1 m über dem Boden%2</translation>
    </message>
    <message>
        <source>lowest point %1 m into the floor (contact)%2</source>
        <translation>tiefster Punkt %1 m im Boden (Kontakt)%2</translation>
    </message>
    <message>
        <source>; last left the floor at t = %1 s</source>
        <translation>; zuletzt vom Boden abgehoben bei t = %1 s</translation>
    </message>
    <message>
        <source>inner layer: %1 %2, pressure %3 %4</source>
        <translation>innere Schicht: %1 %2, Druck %3 %4</translation>
    </message>
    <message>
        <source>measuring on the parameters in use…</source>
        <translation>Messung mit den aktuellen Parametern…</translation>
    </message>
    <message>
        <source>Run until a time, a stopwatch, and each answer of the lesson beside what your run gives</source>
        <translation>Laufen bis zu einer Zeit, eine Stoppuhr, und jede Antwort der Lektion neben dem, was Ihr Lauf ergibt</translation>
    </message>
    <message>
        <source>Run until this simulated time</source>
        <translation>Laufen bis zu dieser simulierten Zeit</translation>
    </message>
    <message>
        <source>The simulated time [s] at which Run until pauses</source>
        <translation>Die simulierte Zeit [s], bei der „Laufen bis“ anhält</translation>
    </message>
    <message>
        <source>Start or stop the stopwatch on the simulated clock</source>
        <translation>Die Stoppuhr auf der simulierten Uhr starten oder anhalten</translation>
    </message>
    <message>
        <source>Set the stopwatch back to zero</source>
        <translation>Die Stoppuhr auf null zurücksetzen</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; smallest gap %2 m</source>
        <translation>Gesamtimpuls &lt;b&gt;%1 kg m/s&lt;/b&gt;; kleinster Abstand %2 m</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; no gap below %2 m</source>
        <translation>Gesamtimpuls &lt;b&gt;%1 kg m/s&lt;/b&gt;; kein Abstand unter %2 m</translation>
    </message>
    <message>
        <source>body%1: centre velocity %2 m/s, outer %3 %4 of %5 at rest</source>
        <translation>body%1: Schwerpunktgeschwindigkeit %2 m/s, äußere %3 %4 von %5 in Ruhe</translation>
    </message>
    <message>
        <source>area</source>
        <translation>Fläche</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>Volumen</translation>
    </message>
</context>
<context>
    <name>elui::LessonsDialog</name>
    <message>
        <source>Experiments</source>
        <translation>Experimente</translation>
    </message>
    <message>
        <source>Short guided experiments: each sets up a scene, says what to change and what to look at, and gives the answer measured with elastic-lab-cli.</source>
        <translation>Kurze angeleitete Experimente: jedes richtet eine Szene ein, sagt, was zu ändern und worauf zu achten ist, und gibt die mit elastic-lab-cli gemessene Antwort.</translation>
    </message>
    <message>
        <source>The guided experiments; the arrow keys choose one, its text is beside the list</source>
        <translation>Die angeleiteten Experimente; die Pfeiltasten wählen eines, sein Text steht neben der Liste</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Experiment</translation>
    </message>
    <message>
        <source>What the chosen experiment sets up, what to change and what to look for</source>
        <translation>Was das gewählte Experiment einrichtet, was zu ändern und worauf zu achten ist</translation>
    </message>
    <message>
        <source>Set up this experiment</source>
        <translation>Dieses Experiment einrichten</translation>
    </message>
    <message>
        <source>Set up the chosen experiment in the main window: its scene, parameters and docks</source>
        <translation>Das gewählte Experiment im Hauptfenster einrichten: seine Szene, Parameter und Docks</translation>
    </message>
    <message>
        <source>Close the experiments; the main window keeps its scene</source>
        <translation>Die Experimente schließen; das Hauptfenster behält seine Szene</translation>
    </message>
</context>
<context>
    <name>elui::MainWindow</name>
    <message>
        <source>Elastic Lab</source>
        <translation>Elastic Lab</translation>
    </message>
    <message>
        <source>&amp;Open scene...</source>
        <translation>Szene ö&amp;ffnen...</translation>
    </message>
    <message>
        <source>A scene file (.json): scene, parameters, integrator and, if saved, the exact state</source>
        <translation>Eine Szenendatei (.json): Szene, Parameter, Integrator und, falls gespeichert, der exakte Zustand</translation>
    </message>
    <message>
        <source>&amp;Save scene</source>
        <translation>Szene &amp;speichern</translation>
    </message>
    <message>
        <source>Scene, every parameter, the integrator and the exact current state</source>
        <translation>Szene, alle Parameter, der Integrator und der exakte aktuelle Zustand</translation>
    </message>
    <message>
        <source>Save scene &amp;as...</source>
        <translation>Szene speichern &amp;unter...</translation>
    </message>
    <message>
        <source>Export &amp;Data (CSV, Excel)...</source>
        <translation>&amp;Daten exportieren (CSV, Excel)...</translation>
    </message>
    <message>
        <source>The time series of this run, with the same columns as elastic-lab-cli run --csv</source>
        <translation>Die Zeitreihe dieses Laufs, mit denselben Spalten wie elastic-lab-cli run --csv</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG, PDF)...</source>
        <translation>&amp;Diagramme exportieren (PNG, SVG, PDF)...</translation>
    </message>
    <message>
        <source>Save &amp;viewport screenshot...</source>
        <translation>&amp;Bildschirmfoto der Ansicht speichern...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Beenden</translation>
    </message>
    <message>
        <source>&amp;Run / Pause</source>
        <translation>&amp;Start / Pause</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Schritt</translation>
    </message>
    <message>
        <source>R&amp;eset</source>
        <translation>&amp;Zurücksetzen</translation>
    </message>
    <message>
        <source>Reset &amp;view</source>
        <translation>Ansicht zu&amp;rücksetzen</translation>
    </message>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>&amp;Präsentationsmodus</translation>
    </message>
    <message>
        <source>Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector</source>
        <translation>Alles %1-mal größer, mit großen Knöpfen für Start, Schritt, Zurück und Zurücksetzen: für einen Beamer</translation>
    </message>
    <message>
        <source>&amp;Larger text</source>
        <translation>&amp;Größere Schrift</translation>
    </message>
    <message>
        <source>S&amp;maller text</source>
        <translation>&amp;Kleinere Schrift</translation>
    </message>
    <message>
        <source>Structural springs</source>
        <translation>Strukturfedern</translation>
    </message>
    <message>
        <source>Radius springs</source>
        <translation>Radialfedern</translation>
    </message>
    <message>
        <source>Shear springs</source>
        <translation>Scherfedern</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Flächen</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normalen</translation>
    </message>
    <message>
        <source>Force vectors</source>
        <translation>Kraftvektoren</translation>
    </message>
    <message>
        <source>Colour springs by strain</source>
        <translation>Federn nach Dehnung färben</translation>
    </message>
    <message>
        <source>Collision box</source>
        <translation>Kollisionsbox</translation>
    </message>
    <message>
        <source>&amp;Side by side...</source>
        <translation>&amp;Nebeneinander...</translation>
    </message>
    <message>
        <source>Single &amp;view</source>
        <translation>&amp;Einzelne Ansicht</translation>
    </message>
    <message>
        <source>Elastic Lab &amp;help</source>
        <translation>&amp;Hilfe zu Elastic Lab</translation>
    </message>
    <message>
        <source>Guided experiments: a scene set up in one click, what to change, what to look at, the measured answer</source>
        <translation>Angeleitete Experimente: eine Szene mit einem Klick eingerichtet, was zu ändern, worauf zu achten ist, die gemessene Antwort</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>Ü&amp;ber</translation>
    </message>
    <message>
        <source>About Elastic Lab</source>
        <translation>Über Elastic Lab</translation>
    </message>
    <message>
        <source>Elastic Lab: the dynamics of two-layer elastic bodies, for teaching.</source>
        <translation>Elastic Lab: die Dynamik zweischichtiger elastischer Körper, für den Unterricht.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Datei</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>&amp;Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ansicht</translation>
    </message>
    <message>
        <source>&amp;High contrast</source>
        <translation>&amp;Hoher Kontrast</translation>
    </message>
    <message>
        <source>White text on black, yellow highlight and focus: for low vision and projectors</source>
        <translation>Weiße Schrift auf Schwarz, gelbe Hervorhebung und gelber Fokus: bei Sehschwäche und für Beamer</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Vergleichen</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Voreinstellungen</translation>
    </message>
    <message>
        <source>S&amp;tudies</source>
        <translation>S&amp;tudien</translation>
    </message>
    <message>
        <source>&amp;Work-precision study...</source>
        <translation>&amp;Aufwand-Genauigkeits-Studie...</translation>
    </message>
    <message>
        <source>&amp;Refinement study...</source>
        <translation>&amp;Verfeinerungsstudie...</translation>
    </message>
    <message>
        <source>&amp;Stability scan...</source>
        <translation>&amp;Stabilitätsscan...</translation>
    </message>
    <message>
        <source>&amp;Long-time energy...</source>
        <translation>&amp;Energie über lange Zeit...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Hilfe</translation>
    </message>
    <message>
        <source>DT set to %1 s</source>
        <translation>DT auf %1 s gesetzt</translation>
    </message>
    <message>
        <source>Use implicit-euler</source>
        <translation>implicit-euler verwenden</translation>
    </message>
    <message>
        <source>Linearised backward Euler: stable at any DT (and damps more)</source>
        <translation>Linearisiertes Rückwärts-Euler: stabil bei jedem DT (und dämpft stärker)</translation>
    </message>
    <message>
        <source>Keep DT</source>
        <translation>DT behalten</translation>
    </message>
    <message>
        <source>Run with this DT anyway (to watch the method fail, for example)</source>
        <translation>Trotzdem mit diesem DT laufen (etwa, um das Verfahren scheitern zu sehen)</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3, which this display does not offer.
Plots, parameters and exports still work.</source>
        <translation>Die 3D-Ansicht braucht OpenGL 3.3, das diese Anzeige nicht bietet.
Diagramme, Parameter und Exporte funktionieren weiterhin.</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Szene öffnen</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>Konnte %1 nicht öffnen: %2</translation>
    </message>
    <message>
        <source>Cannot build that body: %1</source>
        <translation>Dieser Körper lässt sich nicht bauen: %1</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Sprache</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Systemsprache</translation>
    </message>
    <message>
        <source>Applies at the next start (now: %1)</source>
        <translation>Gilt ab dem nächsten Start (jetzt: %1)</translation>
    </message>
    <message>
        <source>The language changes when Elastic Lab starts again.</source>
        <translation>Die Sprache wechselt beim nächsten Start von Elastic Lab.</translation>
    </message>
    <message>
        <source>Language: %1 at the next start</source>
        <translation>Sprache: %1 ab dem nächsten Start</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Sprache</translation>
    </message>
    <message>
        <source>Class controls</source>
        <translation>Unterrichtsknöpfe</translation>
    </message>
    <message>
        <source>Presentation mode: text %1x (Ctrl+= larger, Ctrl+- smaller, F5 off)</source>
        <translation>Präsentationsmodus: Schrift %1-fach (Strg+= größer, Strg+- kleiner, F5 aus)</translation>
    </message>
    <message>
        <source>Normal text size</source>
        <translation>Normale Schriftgröße</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Ungespeicherte Änderungen</translation>
    </message>
    <message>
        <source>The parameters or the integrator of %1 have changed since it was saved.</source>
        <translation>Die Parameter oder der Integrator von %1 haben sich seit dem Speichern geändert.</translation>
    </message>
    <message>
        <source>Save stores the changes and the current state in the file.</source>
        <translation>Speichern legt die Änderungen und den aktuellen Zustand in der Datei ab.</translation>
    </message>
    <message>
        <source> Press Run (Space).</source>
        <translation> Drücken Sie Start (Leertaste).</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Start</translation>
    </message>
    <message>
        <source>&lt;b&gt;This body is likely unstable at the current DT.&lt;/b&gt; %1. The run is paused.</source>
        <translation>&lt;b&gt;Dieser Körper ist beim aktuellen DT wahrscheinlich instabil.&lt;/b&gt; %1. Der Lauf ist angehalten.</translation>
    </message>
    <message>
        <source>Use DT = %1 s</source>
        <translation>DT = %1 s verwenden</translation>
    </message>
    <message>
        <source>Elastic Lab — %1</source>
        <translation>Elastic Lab — %1</translation>
    </message>
    <message>
        <source>%1[*] — Elastic Lab (%2)</source>
        <translation>%1[*] — Elastic Lab (%2)</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(keiner)</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>&amp;Leeren</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json);;All files (*)</source>
        <translation>Elastic-Lab-Szenen (*.json);;Alle Dateien (*)</translation>
    </message>
    <message>
        <source>Could not open %1: not a regular file</source>
        <translation>Konnte %1 nicht öffnen: keine normale Datei</translation>
    </message>
    <message>
        <source>Could not open %1: no such file</source>
        <translation>Konnte %1 nicht öffnen: keine solche Datei</translation>
    </message>
    <message>
        <source>Could not open %1: %2 bytes is too large for a scene file</source>
        <translation>Konnte %1 nicht öffnen: %2 Bytes sind zu groß für eine Szenendatei</translation>
    </message>
    <message>
        <source>%1 is not a scene this program can open:
%2</source>
        <translation>%1 ist keine Szene, die dieses Programm öffnen kann:
%2</translation>
    </message>
    <message>
        <source>Opened %1: the saved state at t = %2 s, paused. Press Run (Space).</source>
        <translation>%1 geöffnet: der gespeicherte Zustand bei t = %2 s, angehalten. Drücken Sie Start (Leertaste).</translation>
    </message>
    <message>
        <source>Opened %1 (no saved state: starts at t = 0). Press Run (Space).</source>
        <translation>%1 geöffnet (kein gespeicherter Zustand: beginnt bei t = 0). Drücken Sie Start (Leertaste).</translation>
    </message>
    <message>
        <source>%1 no longer exists; it has been removed from the recent files.</source>
        <translation>%1 existiert nicht mehr; die Datei wurde aus den zuletzt geöffneten entfernt.</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Zuletzt geöffnet</translation>
    </message>
    <message>
        <source>Save scene as</source>
        <translation>Szene speichern unter</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json)</source>
        <translation>Elastic-Lab-Szenen (*.json)</translation>
    </message>
    <message>
        <source>Could not save %1: no scene is running yet</source>
        <translation>Konnte %1 nicht speichern: es läuft noch keine Szene</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Szene speichern</translation>
    </message>
    <message>
        <source>Saved the first view (%1) at t = %2 s to %3; %4 not in the file.</source>
        <translation>Die erste Ansicht (%1) bei t = %2 s in %3 gespeichert; %4 nicht in der Datei.</translation>
    </message>
    <message>
        <source>the second view is</source>
        <translation>die zweite Ansicht ist</translation>
    </message>
    <message>
        <source>the other views are</source>
        <translation>die anderen Ansichten sind</translation>
    </message>
    <message>
        <source>Saved %1 at t = %2 s (%3).</source>
        <translation>%1 bei t = %2 s gespeichert (%3).</translation>
    </message>
    <message>
        <source>CSV, comma and decimal point (*.csv)</source>
        <translation>CSV, Komma und Dezimalpunkt (*.csv)</translation>
    </message>
    <message>
        <source>CSV for spreadsheets, semicolon and decimal comma (*.csv)</source>
        <translation>CSV für Tabellenkalkulationen, Semikolon und Dezimalkomma (*.csv)</translation>
    </message>
    <message>
        <source>Excel workbook with charts (*.xlsx)</source>
        <translation>Excel-Arbeitsmappe mit Diagrammen (*.xlsx)</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Daten exportieren</translation>
    </message>
    <message>
        <source>Wrote %1 rows to %2</source>
        <translation>%1 Zeilen nach %2 geschrieben</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>Diagramme exportieren</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>PNG-Bild (*.png);;SVG-Zeichnung (*.svg);;PDF-Dokument (*.pdf)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Save viewport screenshot</source>
        <translation>Bildschirmfoto der Ansicht speichern</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>PNG-Bild (*.png)</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Bildschirmfoto speichern</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Schritt &amp;zurück</translation>
    </message>
    <message>
        <source>Timeline s&amp;tart</source>
        <translation>Zeitleisten-&amp;Anfang</translation>
    </message>
    <message>
        <source>Timeline &amp;newest</source>
        <translation>&amp;Neuester Zeitpunkt</translation>
    </message>
    <message>
        <source>&amp;Clear abandoned future</source>
        <translation>Verworfene &amp;Zukunft entfernen</translation>
    </message>
    <message>
        <source>Velocity vectors</source>
        <translation>Geschwindigkeitsvektoren</translation>
    </message>
    <message>
        <source>Ruler (drag to measure)</source>
        <translation>Lineal (ziehen zum Messen)</translation>
    </message>
    <message>
        <source>Lesson &amp;texts (Experiments)...</source>
        <translation>Lektions&amp;texte (Experimente)...</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Lektionen</translation>
    </message>
    <message>
        <source>%1: set up. Lessons &gt; Lesson texts says what to change and what to look at. Press Run (Space).</source>
        <translation>%1: eingerichtet. Lektionen &gt; Lektionstexte sagt, was zu ändern und worauf zu achten ist. Drücken Sie Start (Leertaste).</translation>
    </message>
    <message>
        <source>Plotting the %1 against time (the Measured dock).</source>
        <translation>Gegen die Zeit gezeichnet: %1 (das Dock Gemessen).</translation>
    </message>
    <message>
        <source>Particle %1</source>
        <translation>Teilchen %1</translation>
    </message>
    <message>
        <source>Plot its height</source>
        <translation>Seine Höhe zeichnen</translation>
    </message>
    <message>
        <source>Plot its speed</source>
        <translation>Seine Geschwindigkeit zeichnen</translation>
    </message>
    <message>
        <source>Plot the inner layer&apos;s centre height</source>
        <translation>Die Höhe des Mittelpunkts der inneren Schicht zeichnen</translation>
    </message>
    <message>
        <source>Plot the outer layer&apos;s centre height</source>
        <translation>Die Höhe des Mittelpunkts der äußeren Schicht zeichnen</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Körper</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass height</source>
        <translation>Die Höhe des Schwerpunkts zeichnen</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass speed</source>
        <translation>Die Geschwindigkeit des Schwerpunkts zeichnen</translation>
    </message>
    <message>
        <source>Plot the layers&apos; separation</source>
        <translation>Den Abstand der Schichten zeichnen</translation>
    </message>
    <message>
        <source>Several &amp;bodies</source>
        <translation>Mehrere &amp;Körper</translation>
    </message>
    <message>
        <source>%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body selector. Press Run (Space).</source>
        <translation>%1: mehrere Körper. Das Dock „Körper“ zeigt Impuls und min_gap; „Parameter“ hat eine Körperauswahl. Drücken Sie Start (Leertaste).</translation>
    </message>
    <message>
        <source>Long-time energy</source>
        <translation>Langzeit-Energie</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>Nebeneinander</translation>
    </message>
</context>
<context>
    <name>elui::MeasurePlotDock</name>
    <message>
        <source>Measured</source>
        <translation>Gemessen</translation>
    </message>
    <message>
        <source>Right-click a particle or the body in the view to plot it here.</source>
        <translation>Klicken Sie mit rechts auf ein Teilchen oder den Körper in der Ansicht, um es hier zu zeichnen.</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Alle entfernen</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>length [m]</source>
        <translation>Länge [m]</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>Geschwindigkeit [m/s]</translation>
    </message>
</context>
<context>
    <name>elui::Pacer</name>
    <message>
        <source>Real time</source>
        <translation>Echtzeit</translation>
    </message>
    <message>
        <source>1/4 speed</source>
        <translation>1/4 Geschwindigkeit</translation>
    </message>
    <message>
        <source>1/10 speed</source>
        <translation>1/10 Geschwindigkeit</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>So schnell wie möglich</translation>
    </message>
</context>
<context>
    <name>elui::ParameterDock</name>
    <message>
        <source>Parameters</source>
        <translation>Parameter</translation>
    </message>
    <message>
        <source>Every parameter of the scene with its unit; a change applies at once</source>
        <translation>Alle Parameter der Szene mit ihrer Einheit; eine Änderung gilt sofort</translation>
    </message>
    <message>
        <source>Reset all to the scene&apos;s defaults</source>
        <translation>Alle auf Standardwerte</translation>
    </message>
    <message>
        <source>Every parameter here (and DT) back to the scene&apos;s default; the body&apos;s shape stays (Scene dock).</source>
        <translation>Jeder Parameter hier (und DT) zurück auf den Standardwert der Szene; die Form des Körpers bleibt (Szene-Dock).</translation>
    </message>
    <message>
        <source>The body whose parameters are shown and edited; world parameters (gravity, box, contact, dt) are every body&apos;s.</source>
        <translation>Der Körper, dessen Parameter gezeigt und bearbeitet werden; Weltparameter (Schwerkraft, Kasten, Kontakt, dt) gelten für jeden Körper.</translation>
    </message>
    <message>
        <source>body%1 (%2)</source>
        <translation>body%1 (%2)</translation>
    </message>
    <message>
        <source>every body</source>
        <translation>jeder Körper</translation>
    </message>
</context>
<context>
    <name>elui::ParameterForm</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;default: %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;Standard: %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;allowed: %4&lt;br&gt;default: %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;erlaubt: %4&lt;br&gt;Standard: %5</translation>
    </message>
    <message>
        <source>Set DT in the Run dock.</source>
        <translation>DT im Lauf-Dock einstellen.</translation>
    </message>
    <message>
        <source>key: %1</source>
        <translation>Schlüssel: %1</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number; allowed %3</source>
        <translation>%1: ‚%2‘ ist keine Zahl; erlaubt %3</translation>
    </message>
    <message>
        <source>%1 = %2 is not allowed; allowed %3%4</source>
        <translation>%1 = %2 ist nicht erlaubt; erlaubt %3%4</translation>
    </message>
    <message>
        <source>, whole numbers</source>
        <translation>, ganze Zahlen</translation>
    </message>
    <message>
        <source>Back to the default: %1</source>
        <translation>Zurück zum Standardwert: %1</translation>
    </message>
    <message>
        <source>Back to the default: %1 %2</source>
        <translation>Zurück zum Standardwert: %1 %2</translation>
    </message>
    <message>
        <source>%1 from %2 to %3 %4%5 (the field takes any value in %6)</source>
        <translation>%1 von %2 bis %3 %4%5 (das Feld nimmt jeden Wert in %6)</translation>
    </message>
    <message>
        <source>, logarithmic</source>
        <translation>, logarithmisch</translation>
    </message>
</context>
<context>
    <name>elui::PlotDock</name>
    <message>
        <source>Plots</source>
        <translation>Diagramme</translation>
    </message>
    <message>
        <source>Last 5 s</source>
        <translation>Letzte 5 s</translation>
    </message>
    <message>
        <source>Last 10 s</source>
        <translation>Letzte 10 s</translation>
    </message>
    <message>
        <source>Last 30 s</source>
        <translation>Letzte 30 s</translation>
    </message>
    <message>
        <source>Full history</source>
        <translation>Gesamter Verlauf</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Automatisch skalieren</translation>
    </message>
    <message>
        <source>Fit the axes to the data; off while you zoom (wheel) and pan (drag)</source>
        <translation>Achsen an die Daten anpassen; aus, während Sie zoomen (Mausrad) und verschieben (Ziehen)</translation>
    </message>
    <message>
        <source>Show per-step error band</source>
        <translation>Fehlerband pro Schritt zeigen</translation>
    </message>
    <message>
        <source>A band around volume, pressure and total energy: the integrator&apos;s local error estimate of each step carried to them (|O(y + e) - O(y)|): the error one step adds, not the error of the run so far, which can be far larger. rk45, CVODE and step doubling have an estimate; other methods show no band.</source>
        <translation>Ein Band um Volumen, Druck und Gesamtenergie: die lokale Fehlerschätzung des Integrators für jeden Schritt, auf sie übertragen (|O(y + e) - O(y)|): der Fehler, den ein Schritt hinzufügt, nicht der bisherige Fehler des Laufs, der weit größer sein kann. rk45, CVODE und Schrittverdopplung haben eine Schätzung; andere Verfahren zeigen kein Band.</translation>
    </message>
    <message>
        <source>Time window of the plots</source>
        <translation>Zeitfenster der Diagramme</translation>
    </message>
    <message>
        <source>How much of the run the plots show: the last seconds, or all of it</source>
        <translation>Wie viel des Laufs die Diagramme zeigen: die letzten Sekunden oder alles</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Zeigen</translation>
    </message>
    <message>
        <source>Energy drift per view</source>
        <translation>Energiedrift je Ansicht</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|drift| [J]</source>
        <translation>|Drift| [J]</translation>
    </message>
    <message>
        <source>✕ a view failed</source>
        <translation>✕ eine Ansicht ist gescheitert</translation>
    </message>
    <message>
        <source>%1 against simulated time; the numbers are in the Run dock&apos;s readout and in File &gt; Export Data</source>
        <translation>%1 gegen die simulierte Zeit; die Zahlen stehen in der Anzeige des Lauf-Docks und unter Datei &gt; Daten exportieren</translation>
    </message>
    <message>
        <source>total</source>
        <translation>gesamt</translation>
    </message>
    <message>
        <source> (abandoned)</source>
        <translation> (verworfen)</translation>
    </message>
    <message>
        <source> error band</source>
        <translation> Fehlerband</translation>
    </message>
    <message>
        <source>No band: this integrator gives no error estimate. Use rk45, CVODE, or tick &quot;Estimate error (step doubling)&quot; in the Run dock.</source>
        <translation>Kein Band: dieser Integrator liefert keine Fehlerschätzung. Verwenden Sie rk45, CVODE, oder kreuzen Sie im Lauf-Dock „Fehler schätzen (Schrittverdopplung)“ an.</translation>
    </message>
    <message>
        <source>The band is there but thinner than a line: each step&apos;s error estimate is below half a pixel at this zoom (an adaptive method keeps it under its tolerance). Loosen rtol/atol in the Run dock, or use a fixed-step method at a larger DT with step doubling, to see it.</source>
        <translation>Das Band ist da, aber dünner als eine Linie: die Fehlerschätzung jedes Schritts liegt bei diesem Zoom unter einem halben Pixel (ein adaptives Verfahren hält sie unter seiner Toleranz). Lockern Sie rtol/atol im Lauf-Dock oder verwenden Sie ein Verfahren mit fester Schrittweite bei größerem DT mit Schrittverdopplung, um es zu sehen.</translation>
    </message>
    <message>
        <source>Band: the error each step adds (a per-step estimate), not the error of the run so far.</source>
        <translation>Band: der Fehler, den jeder Schritt hinzufügt (eine Schätzung pro Schritt), nicht der bisherige Fehler des Laufs.</translation>
    </message>
    <message>
        <source>t = %1 s</source>
        <translation>t = %1 s</translation>
    </message>
    <message>
        <source> ✕ %1 s</source>
        <translation> ✕ %1 s</translation>
    </message>
    <message>
        <source>Volume, pressure and energy against simulated time, one plot under the other</source>
        <translation>Volumen, Druck und Energie gegen die simulierte Zeit, ein Diagramm unter dem anderen</translation>
    </message>
    <message>
        <source>Reference curve (rk45)</source>
        <translation>Referenzkurve (rk45)</translation>
    </message>
    <message>
        <source>A converged solution (rk45 at tolerance 1e-10) from the run&apos;s start, computed beside the run on a thread of its own and drawn dashed: the distance between a curve and it is the error of the run so far (the global error), where the band is the error one step adds. It follows the run up to the first change of the physics (a parameter edit other than DT, or a drag).</source>
        <translation>Eine konvergierte Lösung (rk45 mit Toleranz 1e-10) ab dem Start des Laufs, neben dem Lauf in einem eigenen Thread berechnet und gestrichelt gezeichnet: der Abstand einer Kurve zu ihr ist der bisherige Fehler des Laufs (der globale Fehler), während das Band der Fehler ist, den ein Schritt hinzufügt. Sie folgt dem Lauf bis zur ersten Änderung der Physik (eine Parameteränderung außer DT, oder ein Ziehen).</translation>
    </message>
    <message>
        <source>reference (rk45, 1e-10)</source>
        <translation>Referenz (rk45, 1e-10)</translation>
    </message>
    <message>
        <source>Reference: computing from the run&apos;s start…</source>
        <translation>Referenz: wird ab dem Start des Laufs berechnet…</translation>
    </message>
    <message>
        <source>At t = %1 s the run&apos;s total energy is %2 J from the reference: the error of the run so far.</source>
        <translation>Bei t = %1 s liegt die Gesamtenergie des Laufs %2 J neben der Referenz: der bisherige Fehler des Laufs.</translation>
    </message>
    <message>
        <source>The band there, one step&apos;s error: ±%1 J.</source>
        <translation>Das Band dort, der Fehler eines Schritts: ±%1 J.</translation>
    </message>
    <message>
        <source>The reference itself failed at t = %1 s (%2): the body fails at every step size.</source>
        <translation>Die Referenz selbst ist bei t = %1 s gescheitert (%2): der Körper scheitert bei jeder Schrittweite.</translation>
    </message>
    <message>
        <source>The run was changed at t = %1 s (a parameter edit or a drag): the reference stops there.</source>
        <translation>Der Lauf wurde bei t = %1 s geändert (eine Parameteränderung oder ein Ziehen): die Referenz endet dort.</translation>
    </message>
    <message>
        <source>The reference has reached t = %1 s (computing).</source>
        <translation>Die Referenz hat t = %1 s erreicht (wird berechnet).</translation>
    </message>
</context>
<context>
    <name>elui::PvDock</name>
    <message>
        <source>P–V diagram</source>
        <translation>P–V-Diagramm</translation>
    </message>
    <message>
        <source>Whole curve (0.5 to 1.5 × rest volume)</source>
        <translation>Ganze Kurve (0,5 bis 1,5 × Ruhevolumen)</translation>
    </message>
    <message>
        <source>Off: the axes fit the trail, to see it move. On: a wide stretch of the isotherm, to see where on it the layer sits.</source>
        <translation>Aus: die Achsen passen sich der Spur an, um sie sich bewegen zu sehen. An: ein weiter Abschnitt der Isotherme, um zu sehen, wo auf ihr die Schicht liegt.</translation>
    </message>
    <message>
        <source>inner layer</source>
        <translation>innere Schicht</translation>
    </message>
    <message>
        <source>outer layer</source>
        <translation>äußere Schicht</translation>
    </message>
    <message>
        <source>Pressure against volume, %1</source>
        <translation>Druck gegen Volumen, %1</translation>
    </message>
    <message>
        <source>The trail of the layer&apos;s gas in the P-V plane and its isotherm</source>
        <translation>Die Spur des Gases der Schicht in der P-V-Ebene und seine Isotherme</translation>
    </message>
    <message>
        <source>P–V, %1</source>
        <translation>P–V, %1</translation>
    </message>
    <message>
        <source>trail</source>
        <translation>Spur</translation>
    </message>
    <message>
        <source>now</source>
        <translation>jetzt</translation>
    </message>
    <message>
        <source>area V [m²]</source>
        <translation>Fläche V [m²]</translation>
    </message>
    <message>
        <source>volume V [m³]</source>
        <translation>Volumen V [m³]</translation>
    </message>
    <message>
        <source>pressure P [N/m]</source>
        <translation>Druck P [N/m]</translation>
    </message>
    <message>
        <source>pressure P [Pa]</source>
        <translation>Druck P [Pa]</translation>
    </message>
    <message>
        <source>%1 has no gas: no P–V diagram.</source>
        <translation>%1 hat kein Gas: kein P–V-Diagramm.</translation>
    </message>
    <message>
        <source>P = nRT/V, nRT = %1 J</source>
        <translation>P = nRT/V, nRT = %1 J</translation>
    </message>
</context>
<context>
    <name>elui::RefinementDialog</name>
    <message>
        <source>Refinement study</source>
        <translation>Verfeinerungsstudie</translation>
    </message>
    <message>
        <source>Values of the scene&apos;s resolution, separated by spaces; the finest is the reference</source>
        <translation>Werte der Auflösung der Szene, durch Leerzeichen getrennt; die feinste ist die Referenz</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatisch</translation>
    </message>
    <message>
        <source>Fixed step DT [s] for every level; it must divide 0.01 s and be stable at the finest level. Empty: a quarter of the smaller of the scene&apos;s DT and the finest level&apos;s stable step</source>
        <translation>Feste Schrittweite DT [s] für jede Stufe; sie muss 0.01 s teilen und auf der feinsten Stufe stabil sein. Leer: ein Viertel des kleineren Werts aus dem DT der Szene und dem stabilen Schritt der feinsten Stufe</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Simulierte Zeit jedes Laufs [s]</translation>
    </message>
    <message>
        <source>Levels</source>
        <translation>Stufen</translation>
    </message>
    <message>
        <source>Levels (%1)</source>
        <translation>Stufen (%1)</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Dauer T [s]</translation>
    </message>
    <message>
        <source>run time [s]</source>
        <translation>Laufzeit [s]</translation>
    </message>
    <message>
        <source>max relative volume error</source>
        <translation>max. relativer Volumenfehler</translation>
    </message>
    <message>
        <source>max centre-of-mass error [m]</source>
        <translation>max. Schwerpunktfehler [m]</translation>
    </message>
    <message>
        <source>Choose exactly one integrator</source>
        <translation>Wählen Sie genau einen Integrator</translation>
    </message>
    <message>
        <source>DT must be a number in seconds, or empty for the automatic step</source>
        <translation>DT muss eine Zahl in Sekunden sein oder leer für den automatischen Schritt</translation>
    </message>
    <message>
        <source>Levels are whole numbers separated by spaces, got &apos;%1&apos;</source>
        <translation>Stufen sind ganze Zahlen, durch Leerzeichen getrennt; erhalten: ‚%1‘</translation>
    </message>
    <message>
        <source>level (%1)</source>
        <translation>Stufe (%1)</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>Teilchen</translation>
    </message>
    <message>
        <source>springs</source>
        <translation>Federn</translation>
    </message>
    <message>
        <source>h [m]</source>
        <translation>h [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>volume error</source>
        <translation>Volumenfehler</translation>
    </message>
    <message>
        <source>centre-of-mass error [m]</source>
        <translation>Schwerpunktfehler [m]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>mesh (%1)</source>
        <translation>Netz (%1)</translation>
    </message>
    <message>
        <source>step (%1=%2, coarser DT)</source>
        <translation>Schritt (%1=%2, gröberes DT)</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Gescheitert: %1</translation>
    </message>
    <message>
        <source>Time error of that step (measured at %1=%2): volume %3, centre of mass %4 m. </source>
        <translation>Zeitfehler dieses Schritts (gemessen bei %1=%2): Volumen %3, Schwerpunkt %4 m. </translation>
    </message>
    <message>
        <source>Spatial order (%1): %2. </source>
        <translation>Räumliche Ordnung (%1): %2. </translation>
    </message>
    <message>
        <source>Spatial order (%1): not resolved. </source>
        <translation>Räumliche Ordnung (%1): nicht aufgelöst. </translation>
    </message>
</context>
<context>
    <name>elui::RunDock</name>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>side by side (see each view)</source>
        <translation>nebeneinander (siehe jede Ansicht)</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>The method that advances the body in time; each one&apos;s order and idea are in its item&apos;s tooltip and in Help</source>
        <translation>Das Verfahren, das den Körper in der Zeit voranbringt; Ordnung und Idee jedes Verfahrens stehen im Tooltip seines Eintrags und in der Hilfe</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>rk45, cvode-bdf and cvode-adams choose their steps so that each step&apos;s error estimate stays below atol + rtol |y| (as elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] (m and m/s). Smaller: smaller steps, more force evaluations, a thinner error band.</source>
        <translation>rk45, cvode-bdf und cvode-adams wählen ihre Schritte so, dass die Fehlerschätzung jedes Schritts unter atol + rtol |y| bleibt (wie elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] (m und m/s). Kleiner: kleinere Schritte, mehr Kraftauswertungen, ein dünneres Fehlerband.</translation>
    </message>
    <message>
        <source>rtol</source>
        <translation>rtol</translation>
    </message>
    <message>
        <source>atol</source>
        <translation>atol</translation>
    </message>
    <message>
        <source>Tolerance</source>
        <translation>Toleranz</translation>
    </message>
    <message>
        <source>How fast simulated time runs against the wall clock</source>
        <translation>Wie schnell die simulierte Zeit gegenüber der Uhr läuft</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Geschwindigkeit</translation>
    </message>
    <message>
        <source>Run or pause the simulation (Space)</source>
        <translation>Simulation starten oder anhalten (Leertaste)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Schritt</translation>
    </message>
    <message>
        <source>One step DT forward (S)</source>
        <translation>Einen Schritt DT vorwärts (S)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Zurücksetzen</translation>
    </message>
    <message>
        <source>Back to the start state with the same parameters (Ctrl+R)</source>
        <translation>Zurück zum Startzustand mit denselben Parametern (Strg+R)</translation>
    </message>
    <message>
        <source>Estimate error (step doubling)</source>
        <translation>Fehler schätzen (Schrittverdopplung)</translation>
    </message>
    <message>
        <source>Fixed-step integrators: estimate the local error by taking each step also as two half steps. Costs about twice the work. rk45 always reports its own estimate.</source>
        <translation>Integratoren mit fester Schrittweite: den lokalen Fehler schätzen, indem jeder Schritt auch als zwei halbe Schritte genommen wird. Kostet etwa doppelt so viel Arbeit. rk45 meldet immer seine eigene Schätzung.</translation>
    </message>
    <message>
        <source>Readout</source>
        <translation>Anzeige</translation>
    </message>
    <message>
        <source>Time, steps, energies and the energy balance of the run</source>
        <translation>Zeit, Schritte, Energien und die Energiebilanz des Laufs</translation>
    </message>
    <message>
        <source>rtol: &apos;%1&apos; is not a number in (0, 1]</source>
        <translation>rtol: ‚%1‘ ist keine Zahl in (0, 1]</translation>
    </message>
    <message>
        <source>atol: &apos;%1&apos; is not a number in [0, 1]</source>
        <translation>atol: ‚%1‘ ist keine Zahl in [0, 1]</translation>
    </message>
    <message>
        <source>Each view</source>
        <translation>Jede Ansicht</translation>
    </message>
    <message>
        <source>view</source>
        <translation>Ansicht</translation>
    </message>
    <message>
        <source>time</source>
        <translation>Zeit</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>Energiedrift</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>gescheitert</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>simulierte Zeit</translation>
    </message>
    <message>
        <source>wall time</source>
        <translation>Rechenzeit</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>Schritte/s</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>angehalten</translation>
    </message>
    <message>
        <source>step taken</source>
        <translation>gemachter Schritt</translation>
    </message>
    <message>
        <source>error estimate</source>
        <translation>Fehlerschätzung</translation>
    </message>
    <message>
        <source>off</source>
        <translation>aus</translation>
    </message>
    <message>
        <source>contact energy</source>
        <translation>Kontaktenergie</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>durch Kontakt entzogen</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>Kraftauswertungen</translation>
    </message>
    <message>
        <source>CVODE steps / RHS</source>
        <translation>CVODE-Schritte / RHS</translation>
    </message>
    <message>
        <source>Jv products / linear it.</source>
        <translation>Jv-Produkte / lineare It.</translation>
    </message>
    <message>
        <source>error-test / conv. failures</source>
        <translation>Fehlertest- / Konv.-Fehlschläge</translation>
    </message>
    <message>
        <source>order, re-initialisations</source>
        <translation>Ordnung, Neuinitialisierungen</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b35900&apos;&gt;Cannot keep up with real time: showing as fast as it runs.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b35900&apos;&gt;Echtzeit nicht zu halten: es läuft so schnell, wie es geht.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>order %1: %2</source>
        <translation>Ordnung %1: %2</translation>
    </message>
    <message>
        <source>%1; allowed %2 s</source>
        <translation>%1; erlaubt %2 s</translation>
    </message>
    <message>
        <source>Relative tolerance rtol</source>
        <translation>Relative Toleranz rtol</translation>
    </message>
    <message>
        <source>Absolute tolerance atol</source>
        <translation>Absolute Toleranz atol</translation>
    </message>
    <message>
        <source>Run</source>
        <comment>button: start the simulation</comment>
        <translation>Start</translation>
    </message>
    <message>
        <source>distance&lt;br&gt;to view %1</source>
        <translation>Abstand&lt;br&gt;zu Ansicht %1</translation>
    </message>
    <message>
        <source>double</source>
        <translation>doppelt (64 Bit)</translation>
    </message>
    <message>
        <source>float</source>
        <translation>einfach (32 Bit)</translation>
    </message>
    <message>
        <source>double: state and forces in 64-bit numbers. float: in 32-bit numbers, as fast engines and games compute (euler, midpoint, rk4, symplectic-euler, verlet; one view; no walls or mouse: the run stops at a wall, a held particle steps in double). The readout shows how far the float run is from double.</source>
        <translation>doppelt: Zustand und Kräfte in 64-Bit-Zahlen. einfach: in 32-Bit-Zahlen, wie schnelle Engines und Spiele rechnen (euler, midpoint, rk4, symplectic-euler, verlet; eine Ansicht; keine Wände und keine Maus: der Lauf hält an einer Wand an, ein gehaltenes Teilchen rechnet doppelt genau). Die Anzeige zeigt, wie weit der einfach genaue Lauf vom doppelt genauen entfernt ist.</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <source>precision</source>
        <translation>Genauigkeit</translation>
    </message>
    <message>
        <source>double while held</source>
        <translation>doppelt, solange gehalten</translation>
    </message>
    <message>
        <source>float − double</source>
        <translation>einfach − doppelt</translation>
    </message>
    <message>
        <source>round-off (est.)</source>
        <translation>Rundung (geschätzt)</translation>
    </message>
</context>
<context>
    <name>elui::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Szene</translation>
    </message>
    <message>
        <source>The body to build: a spring, a two-layer ring or a two-layer sphere</source>
        <translation>Der Körper, der gebaut wird: eine Feder, ein zweischichtiger Ring oder eine zweischichtige Kugel</translation>
    </message>
    <message>
        <source>Rebuild body</source>
        <translation>Körper neu bauen</translation>
    </message>
    <message>
        <source>Build the chosen scene with this shape and start again from rest</source>
        <translation>Die gewählte Szene mit dieser Form bauen und aus der Ruhe neu beginnen</translation>
    </message>
    <message>
        <source>Body values</source>
        <translation>Körperwerte</translation>
    </message>
    <message>
        <source>What the parameters mean for the body that runs: under scaling=physical the values hold at the scene&apos;s default resolution and a finer mesh keeps the body&apos;s totals; under scaling=thesis they are per particle and per spring</source>
        <translation>Was die Parameter für den laufenden Körper bedeuten: bei scaling=physical gelten die Werte bei der Standardauflösung der Szene, und ein feineres Netz behält die Gesamtgrößen des Körpers; bei scaling=thesis gelten sie pro Teilchen und pro Feder</translation>
    </message>
    <message>
        <source>This body uses: %1</source>
        <translation>Dieser Körper verwendet: %1</translation>
    </message>
    <message>
        <source>The body to build, its shape and what its parameters mean</source>
        <translation>Der zu bauende Körper, seine Form und was seine Parameter bedeuten</translation>
    </message>
</context>
<context>
    <name>elui::StabilityDialog</name>
    <message>
        <source>Stability scan</source>
        <translation>Stabilitätsscan</translation>
    </message>
    <message>
        <source>Each trial runs this long; a run that does not blow up and whose energy stays bounded is stable</source>
        <translation>Jeder Versuch läuft so lange; ein Lauf, der nicht explodiert und dessen Energie beschränkt bleibt, ist stabil</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Dauer T [s]</translation>
    </message>
    <message>
        <source>largest stable DT [s]</source>
        <translation>größtes stabiles DT [s]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>linearising</source>
        <translation>Linearisierung</translation>
    </message>
    <message>
        <source>stable DT [s]</source>
        <translation>stabiles DT [s]</translation>
    </message>
    <message>
        <source>unstable DT [s]</source>
        <translation>instabiles DT [s]</translation>
    </message>
    <message>
        <source>predicted DT [s]</source>
        <translation>vorhergesagtes DT [s]</translation>
    </message>
    <message>
        <source>h·ω at stable</source>
        <translation>h·ω bei stabil</translation>
    </message>
    <message>
        <source>why it failed above</source>
        <translation>warum es darüber scheiterte</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>gemessen</translation>
    </message>
    <message>
        <source>linearised prediction</source>
        <translation>linearisierte Vorhersage</translation>
    </message>
    <message>
        <source>Highest mode of the linearised body: ω = %1 rad/s (damping %2 1/s), %3 free coordinates. A method is stable at DT when no mode grows; measured by bisection over %4 s runs.</source>
        <translation>Höchste Mode des linearisierten Körpers: ω = %1 rad/s (Dämpfung %2 1/s), %3 freie Koordinaten. Ein Verfahren ist bei DT stabil, wenn keine Mode wächst; gemessen durch Bisektion über Läufe von %4 s.</translation>
    </message>
    <message>
        <source>Duration must be a positive number of seconds</source>
        <translation>Die Dauer muss eine positive Zahl von Sekunden sein</translation>
    </message>
</context>
<context>
    <name>elui::StabilityMapDock</name>
    <message>
        <source>Stability map</source>
        <translation>Stabilitätskarte</translation>
    </message>
    <message>
        <source>The integrator&apos;s stability region and the body&apos;s eigenvalues times DT; the margin is written below the map</source>
        <translation>Das Stabilitätsgebiet des Integrators und die Eigenwerte des Körpers mal DT; der Abstand steht unter der Karte</translation>
    </message>
    <message>
        <source>Re(hλ)</source>
        <translation>Re(hλ)</translation>
    </message>
    <message>
        <source>Im(hλ)</source>
        <translation>Im(hλ)</translation>
    </message>
    <message>
        <source>stable region</source>
        <translation>Stabilitätsgebiet</translation>
    </message>
    <message>
        <source>DT·λ, every mode</source>
        <translation>DT·λ, alle Moden</translation>
    </message>
    <message>
        <source>leaves first</source>
        <translation>verlässt zuerst</translation>
    </message>
    <message>
        <source>measured limit</source>
        <translation>gemessene Grenze</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>Ausprobieren</translation>
    </message>
    <message>
        <source>Waiting for a body…</source>
        <translation>Warte auf einen Körper…</translation>
    </message>
    <message>
        <source>Linearising the body…</source>
        <translation>Der Körper wird linearisiert…</translation>
    </message>
    <message>
        <source>edge (radius 1)</source>
        <translation>Rand (Radius 1)</translation>
    </message>
    <message>
        <source>edge |R| = 1</source>
        <translation>Rand |R| = 1</translation>
    </message>
    <message>
        <source>edge of view %1 (%2)</source>
        <translation>Rand von Ansicht %1 (%2)</translation>
    </message>
    <message>
        <source>Re(hλ), h = DT = %1 s</source>
        <translation>Re(hλ), h = DT = %1 s</translation>
    </message>
    <message>
        <source>View %1, %2 (filled): %3</source>
        <translation>Ansicht %1, %2 (gefüllt): %3</translation>
    </message>
    <message>
        <source>View %1, %2 (dashed): %3</source>
        <translation>Ansicht %1, %2 (gestrichelt): %3</translation>
    </message>
    <message>
        <source>Eigenvalues: %1.
%2</source>
        <translation>Eigenwerte: %1.
%2</translation>
    </message>
    <message>
        <source>%1 has no fixed stability limit to measure</source>
        <translation>%1 hat keine feste Stabilitätsgrenze, die sich messen ließe</translation>
    </message>
    <message>
        <source>Measured: no stable DT down to 1e-5 s.</source>
        <translation>Gemessen: kein stabiles DT bis hinab zu 1e-5 s.</translation>
    </message>
    <message>
        <source>Measured: stable up to the largest DT scanned, %1 s</source>
        <translation>Gemessen: stabil bis zum größten untersuchten DT, %1 s</translation>
    </message>
    <message>
        <source>Measured: stable at DT = %1 s, blows up at %2 s</source>
        <translation>Gemessen: stabil bei DT = %1 s, explodiert bei %2 s</translation>
    </message>
    <message>
        <source> (%1 runs of %2 s; predicted %3 s).</source>
        <translation> (%1 Läufe von %2 s; vorhergesagt %3 s).</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>unbegrenzt</translation>
    </message>
    <message>
        <source> ✕ = the ringed mode at the measured DT.</source>
        <translation> ✕ = die eingekreiste Mode beim gemessenen DT.</translation>
    </message>
    <message>
        <source> ✕ = the fastest mode at the measured DT.</source>
        <translation> ✕ = die schnellste Mode beim gemessenen DT.</translation>
    </message>
    <message>
        <source>Measuring the largest stable DT of %1…</source>
        <translation>Das größte stabile DT von %1 wird gemessen…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Wird abgebrochen…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Measurement cancelled.</source>
        <translation>Messung abgebrochen.</translation>
    </message>
    <message>
        <source>The body or the integrator changed during the measurement: press Try it again.</source>
        <translation>Körper oder Integrator haben sich während der Messung geändert: drücken Sie erneut Ausprobieren.</translation>
    </message>
    <message>
        <source>Measure this integrator&apos;s largest stable DT on this body or world: the stability scan&apos;s bisection (%1 s runs; Studies → Stability scan does all integrators), marked on the picture</source>
        <translation>Das größte stabile DT dieses Integrators an diesem Körper oder dieser Welt messen: die Bisektion des Stabilitätsscans (Läufe von %1 s; Studien → Stabilitätsscan misst alle Integratoren), im Bild markiert</translation>
    </message>
    <message>
        <source>Linearising the world (%1 bodies)…</source>
        <translation>Die Welt wird linearisiert (%1 Körper)…</translation>
    </message>
    <message>
        <source>The whole world (%1 bodies) linearised as one system: every body&apos;s modes, and the contact between bodies where two are within the contact skin. </source>
        <translation>Die ganze Welt (%1 Körper) als ein System linearisiert: die Moden jedes Körpers und der Kontakt zwischen Körpern, wo zwei innerhalb der Kontakthaut liegen. </translation>
    </message>
    <message>
        <source>the fastest mode</source>
        <translation>die schnellste Mode</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1, a pure decay)</source>
        <translation>die schnellste Mode (hλ = %1, rein abklingend)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1, a pure decay)</source>
        <translation>die Mode (hλ = %1, rein abklingend)</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1 ± %2i)</source>
        <translation>die schnellste Mode (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1 ± %2i)</source>
        <translation>die Mode (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>per mode, modal damping</source>
        <translation>Mode für Mode, modale Dämpfung</translation>
    </message>
    <message>
        <source>xpbd is stable at every DT: no margin to give.</source>
        <translation>xpbd ist bei jedem DT stabil: es gibt keine Grenze, zu der ein Abstand anzugeben wäre.</translation>
    </message>
    <message>
        <source>%1 chooses its own internal steps: no DT limit from stability.</source>
        <translation>%1 wählt seine inneren Schritte selbst: die Stabilität begrenzt DT nicht.</translation>
    </message>
    <message>
        <source>No DT limit: every mode of this body stays in the region for any DT.</source>
        <translation>Keine Grenze für DT: jede Mode dieses Körpers bleibt bei jedem DT im Gebiet.</translation>
    </message>
    <message>
        <source>No DT is stable: a mode pair grows for every DT (%1).</source>
        <translation>Kein DT ist stabil: ein Modenpaar wächst bei jedem DT (%1).</translation>
    </message>
    <message>
        <source>No DT is stable: %1 sits where the region only touches the imaginary axis at 0; it grows for every DT (slowly when DT is small).</source>
        <translation>Kein DT ist stabil: %1 liegt dort, wo das Gebiet die imaginäre Achse nur in 0 berührt; sie wächst bei jedem DT (langsam, wenn DT klein ist).</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before a mode pair goes unstable (%3); the picture is exact for underdamped modes only.</source>
        <translation>DT kann um den Faktor %1 wachsen (bis %2 s), bevor ein Modenpaar instabil wird (%3); das Bild ist nur für unterdämpfte Moden exakt.</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before %3 leaves the region.</source>
        <translation>DT kann um den Faktor %1 wachsen (bis %2 s), bevor %3 das Gebiet verlässt.</translation>
    </message>
    <message>
        <source>DT is already outside the stable range (%1): shrink DT by %2× (to %3 s).</source>
        <translation>DT liegt schon außerhalb des stabilen Bereichs (%1): DT um den Faktor %2 verkleinern (auf %3 s).</translation>
    </message>
    <message>
        <source>DT is already outside: %1 is out of the region; shrink DT by %2× (to %3 s) to bring it back.</source>
        <translation>DT ist schon zu groß: %1 liegt außerhalb des Gebiets; DT um den Faktor %2 verkleinern (auf %3 s), um sie zurückzuholen.</translation>
    </message>
    <message>
        <source>exact spectrum: all %1 eigenvalues of the linearised first-order system (dense eigen-solve)</source>
        <translation>exaktes Spektrum: alle %1 Eigenwerte des linearisierten Systems erster Ordnung (dichte Eigenwertrechnung)</translation>
    </message>
    <message>
        <source>modal: all %1 modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; λ = −c/2 ± i√(ω² − c²/4)</source>
        <translation>modal: alle %1 Moden von M⁻¹K (symmetrisches Eigenwertproblem), Dämpfung c = φᵀ(M⁻¹D)φ je Mode; λ = −c/2 ± i√(ω² − c²/4)</translation>
    </message>
    <message>
        <source>iterative: %1 Ritz values of the first-order system, Arnoldi (%2 steps) on the Jacobian products, %3 free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner ones are not</source>
        <translation>iterativ: %1 Ritz-Werte des Systems erster Ordnung, Arnoldi (%2 Schritte) mit Produkten der Jacobi-Matrix, %3 freie Koordinaten: die äußeren Eigenwerte (größtes |λ|) sind genau, die inneren nicht</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis up to ±%1i: undamped modes are stable up to hω = 2√2.</source>
        <translation>Gebiet: |R(hλ)| ≤ 1 für sein Stabilitätspolynom R (das Taylorpolynom von e^z); es berührt die imaginäre Achse bis ±%1i: ungedämpfte Moden sind bis hω = 2√2 stabil.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis only at 0: an undamped mode grows for every DT.</source>
        <translation>Gebiet: |R(hλ)| ≤ 1 für sein Stabilitätspolynom R (das Taylorpolynom von e^z); es berührt die imaginäre Achse nur in 0: eine ungedämpfte Mode wächst bei jedem DT.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for Dormand–Prince&apos;s 5th-order solution, R = Taylor to z⁵ + z⁶/600, taken at a fixed step. The adaptive run picks its own step from the error tolerance: it does not blow up, it takes smaller steps.</source>
        <translation>Gebiet: |R(hλ)| ≤ 1 für die Lösung 5. Ordnung von Dormand–Prince, R = Taylor bis z⁵ + z⁶/600, bei festem Schritt genommen. Der adaptive Lauf wählt seinen Schritt selbst nach der Fehlertoleranz: er explodiert nicht, er macht kleinere Schritte.</translation>
    </message>
    <message>
        <source>Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| &lt; 1, the whole left half-plane (A-stable): no DT limit from stability.</source>
        <translation>Gebiet: |1/(1 − hλ)| ≤ 1, alles außerhalb der Kreisscheibe |1 − hλ| &lt; 1, die ganze linke Halbebene (A-stabil): die Stabilität begrenzt DT nicht.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Gebiet: kein skalares R; gezeichnet für eine Oszillatormode mit dem Eigenwertpaar hλ, hλ̄ (exakt, wenn die Moden entkoppeln; die reelle Achse zeigt die kritisch gedämpfte Mode). Ungedämpfte Moden: hω ≤ 2. Der Abstand zur Grenze folgt aus der Schrittmatrix, nicht aus dem Bild.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, damping at the half-step velocity (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Gebiet: kein skalares R; gezeichnet für eine Oszillatormode mit dem Eigenwertpaar hλ, hλ̄, Dämpfung mit der Geschwindigkeit des halben Schritts (exakt, wenn die Moden entkoppeln; die reelle Achse zeigt die kritisch gedämpfte Mode). Ungedämpfte Moden: hω ≤ 2. Der Abstand zur Grenze folgt aus der Schrittmatrix, nicht aus dem Bild.</translation>
    </message>
    <message>
        <source>Region: no scalar R; the step is a product of %1 Verlet substeps (some backwards), drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the half-kick velocity, as the integrator does), traced ray by ray from 0. Undamped modes: hω ≤ %2 (a step costs %3 force evaluations). The margin uses the step matrix, not the picture.</source>
        <translation>Gebiet: kein skalares R; der Schritt ist ein Produkt aus %1 Verlet-Teilschritten (einige rückwärts), gezeichnet für eine Oszillatormode mit dem Eigenwertpaar hλ, hλ̄ (Dämpfung mit der Geschwindigkeit des halben Kicks, wie im Integrator), Strahl für Strahl von 0 aus verfolgt. Ungedämpfte Moden: hω ≤ %2 (ein Schritt kostet %3 Kraftauswertungen). Der Abstand zur Grenze folgt aus der Schrittmatrix, nicht aus dem Bild.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed region. BDF1–2 are A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the step or the order when a mode threatens: no DT limit, DT is only the output interval.</source>
        <translation>Kein Gebiet: adaptives BDF-Verfahren variabler Ordnung (Ordnungen 1–5), fehlergesteuert, ohne festes Gebiet. BDF1–2 sind A-stabil, BDF3–5 A(α)-stabil bis α ≈ 51°; CVODE verkleinert Schritt oder Ordnung, sobald eine Mode zu wachsen droht: keine Grenze für DT, DT ist nur das Ausgabeintervall.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed region. Its regions are small (explicit-like); CVODE keeps the internal step inside them by its error test: no DT limit, stiff bodies only cost steps.</source>
        <translation>Kein Gebiet: adaptives Adams-Verfahren variabler Ordnung (Ordnungen 1–12), fehlergesteuert, ohne festes Gebiet. Seine Gebiete sind klein (wie bei expliziten Verfahren); CVODE hält den inneren Schritt durch seinen Fehlertest darin: keine Grenze für DT, steife Körper kosten nur Schritte.</translation>
    </message>
    <message>
        <source>No region: XPBD projects the springs as compliant constraints (compliance 1/ks): unconditionally stable, no region in the hλ plane; large DT costs accuracy (the body turns soft), not stability.</source>
        <translation>Kein Gebiet: XPBD projiziert die Federn als nachgiebige Zwangsbedingungen (Nachgiebigkeit 1/ks): unbedingt stabil, kein Gebiet in der hλ-Ebene; ein großes DT kostet Genauigkeit (der Körper wird weich), nicht Stabilität.</translation>
    </message>
    <message>
        <source>No stability region for %1.</source>
        <translation>Kein Stabilitätsgebiet für %1.</translation>
    </message>
</context>
<context>
    <name>elui::StrainLegend</name>
    <message>
        <source>spring strain</source>
        <translation>Federdehnung</translation>
    </message>
</context>
<context>
    <name>elui::StudyDialogBase</name>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt; with the current parameters</source>
        <translation>Szene: &lt;b&gt;%1&lt;/b&gt; mit den aktuellen Parametern</translation>
    </message>
    <message>
        <source>Include %1 (order %2) in the study: %3</source>
        <translation>%1 (Ordnung %2) in die Studie aufnehmen: %3</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Lauf</translation>
    </message>
    <message>
        <source>Run the study on a worker thread; the window stays usable</source>
        <translation>Die Studie in einem Hintergrund-Thread ausführen; das Fenster bleibt bedienbar</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Abbrechen</translation>
    </message>
    <message>
        <source>Stop the study; the rows finished so far stay</source>
        <translation>Die Studie anhalten; die fertigen Zeilen bleiben</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Exportieren...</translation>
    </message>
    <message>
        <source>Write the table as CSV, or the plot as SVG, PNG or PDF</source>
        <translation>Die Tabelle als CSV oder das Diagramm als SVG, PNG oder PDF schreiben</translation>
    </message>
    <message>
        <source>Study plot</source>
        <translation>Diagramm der Studie</translation>
    </message>
    <message>
        <source>The study&apos;s results drawn; the same numbers are in the table</source>
        <translation>Die Ergebnisse der Studie gezeichnet; dieselben Zahlen stehen in der Tabelle</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Ergebnisse</translation>
    </message>
    <message>
        <source>One row per run of the study; the arrow keys move between the cells</source>
        <translation>Eine Zeile pro Lauf der Studie; die Pfeiltasten bewegen zwischen den Zellen</translation>
    </message>
    <message>
        <source>Cancelled: partial results</source>
        <translation>Abgebrochen: Teilergebnisse</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Fertig</translation>
    </message>
    <message>
        <source>Choose at least one integrator</source>
        <translation>Wählen Sie mindestens einen Integrator</translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation>Wird abgebrochen...</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>CSV-Tabelle (*.csv);;PNG-Diagramm (*.png);;PDF-Diagramm (*.pdf)</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;SVG plot (*.svg);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>CSV-Tabelle (*.csv);;SVG-Diagramm (*.svg);;PNG-Diagramm (*.png);;PDF-Diagramm (*.pdf)</translation>
    </message>
    <message>
        <source>Export results</source>
        <translation>Ergebnisse exportieren</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportieren</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 geschrieben</translation>
    </message>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt;, %2 bodies, with the current parameters (the whole world: every run moves every body)</source>
        <translation>Szene: &lt;b&gt;%1&lt;/b&gt;, %2 Körper, mit den aktuellen Parametern (die ganze Welt: jeder Lauf bewegt jeden Körper)</translation>
    </message>
</context>
<context>
    <name>elui::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>Zeitleiste</translation>
    </message>
    <message>
        <source>|◀ Start</source>
        <translation>|◀ Anfang</translation>
    </message>
    <message>
        <source>The start of the recorded run (Home)</source>
        <translation>Der Anfang des aufgezeichneten Laufs (Pos1)</translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ Schritt zurück</translation>
    </message>
    <message>
        <source>One step back (Shift+S); S steps forward</source>
        <translation>Einen Schritt zurück (Umschalt+S); S geht vorwärts</translation>
    </message>
    <message>
        <source>Newest ▶|</source>
        <translation>Neuester ▶|</translation>
    </message>
    <message>
        <source>The newest recorded moment (End)</source>
        <translation>Der neueste aufgezeichnete Moment (Ende)</translation>
    </message>
    <message>
        <source>Clear abandoned</source>
        <translation>Verworfenes entfernen</translation>
    </message>
    <message>
        <source>Remove the faint lines of the abandoned future from the plots</source>
        <translation>Die blassen Linien der verworfenen Zukunft aus den Diagrammen entfernen</translation>
    </message>
    <message>
        <source>&lt;b&gt;Back in time&lt;/b&gt;: t = %1 s, step %2 of %3 · a change, Run or Step branches here</source>
        <translation>&lt;b&gt;Zurück in der Zeit&lt;/b&gt;: t = %1 s, Schritt %2 von %3 · eine Änderung, Start oder Schritt verzweigt hier</translation>
    </message>
    <message>
        <source>t = %1 s, step %2 (newest) · recorded from t = %3 s</source>
        <translation>t = %1 s, Schritt %2 (neuester) · aufgezeichnet ab t = %3 s</translation>
    </message>
    <message>
        <source>%1 checkpoints / %2 steps · %3 of %4</source>
        <translation>%1 Sicherungspunkte / %2 Schritte · %3 von %4</translation>
    </message>
    <message>
        <source>Every moment of the run: drag, or Tab to it and press the arrow keys (Page Up and Page Down: a twentieth of the run), to travel back in time (the run pauses)</source>
        <translation>Jeder Moment des Laufs: ziehen, oder mit Tab hingehen und die Pfeiltasten drücken (Bild auf und Bild ab: ein Zwanzigstel des Laufs), um in der Zeit zurückzureisen (der Lauf hält an)</translation>
    </message>
</context>
<context>
    <name>elui::Viewport</name>
    <message>
        <source>Simulation view</source>
        <translation>Simulationsansicht</translation>
    </message>
    <message>
        <source>The body. Keyboard: arrow keys or Page Up and Page Down choose a particle and show the forces on it; Enter grabs it with the mouse spring, then the arrow keys drag it (Shift: ten times farther) and Enter or Escape lets go; Escape clears the choice.</source>
        <translation>Der Körper. Tastatur: Pfeiltasten oder Bild auf und Bild ab wählen ein Teilchen und zeigen die Kräfte darauf; Eingabe greift es mit der Mausfeder, dann ziehen die Pfeiltasten es (Umschalt: zehnmal weiter), und Eingabe oder Escape lässt los; Escape hebt die Auswahl auf.</translation>
    </message>
    <message>
        <source>Forces on particle %1</source>
        <translation>Kräfte auf Teilchen %1</translation>
    </message>
    <message>
        <source>total (sum)</source>
        <translation>gesamt (Summe)</translation>
    </message>
    <message>
        <source>arrows: 1 m = %1 N</source>
        <translation>Pfeile: 1 m = %1 N</translation>
    </message>
    <message>
        <source>click elsewhere to clear</source>
        <translation>anderswo klicken zum Aufheben</translation>
    </message>
    <message>
        <source>distance from %1: %2 m (RMS)</source>
        <translation>Abstand zu %1: %2 m (RMS)</translation>
    </message>
    <message>
        <source>Blew up at t = %1 s: %2</source>
        <translation>Explodiert bei t = %1 s: %2</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source> (Δx %1, Δy %2)</source>
        <translation> (Δx %1, Δy %2)</translation>
    </message>
    <message>
        <source>Forces on particle %1 of body %2</source>
        <translation>Kräfte auf Teilchen %1 von Körper %2</translation>
    </message>
    <message>
        <source>momentum %1 kg m/s</source>
        <translation>Impuls %1 kg m/s</translation>
    </message>
    <message>
        <source>min_gap %1 m</source>
        <translation>min_gap %1 m</translation>
    </message>
    <message>
        <source>min_gap beyond %1 m</source>
        <translation>min_gap über %1 m</translation>
    </message>
</context>
<context>
    <name>elui::WorkPrecisionDialog</name>
    <message>
        <source>Work-precision study</source>
        <translation>Aufwand-Genauigkeits-Studie</translation>
    </message>
    <message>
        <source>Fixed steps DT [s], separated by spaces; T must be a multiple of each</source>
        <translation>Feste Schritte DT [s], durch Leerzeichen getrennt; T muss ein Vielfaches jedes Schritts sein</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Simulierte Zeit jedes Laufs [s]</translation>
    </message>
    <message>
        <source>What the errors are measured against: the closed form where there is one (exact), or a run of rk4 or rk45 with a much smaller step; auto chooses</source>
        <translation>Wogegen die Fehler gemessen werden: die geschlossene Lösung, wo es eine gibt (exact), oder ein Lauf von rk4 oder rk45 mit viel kleinerem Schritt; auto wählt</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referenz</translation>
    </message>
    <message>
        <source>Each point is timed this many times; the plot shows the median run time with a band from the first to the third quartile (the same binary runs at two speeds on a shared machine)</source>
        <translation>Jeder Punkt wird so oft gemessen; das Diagramm zeigt die mediane Laufzeit mit einem Band vom ersten bis zum dritten Quartil (dasselbe Programm läuft auf einem geteilten Rechner verschieden schnell)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>keiner</translation>
    </message>
    <message>
        <source>A run that takes longer [s] is recorded as not reached (no error), and so is every costlier point of its integrator: the curve stops there</source>
        <translation>Ein Lauf, der länger dauert [s], gilt als nicht erreicht (kein Fehler), ebenso jeder aufwendigere Punkt seines Integrators: die Kurve endet dort</translation>
    </message>
    <message>
        <source>DT values [s]</source>
        <translation>DT-Werte [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Dauer T [s]</translation>
    </message>
    <message>
        <source>Timed runs per point</source>
        <translation>Gemessene Läufe pro Punkt</translation>
    </message>
    <message>
        <source>Time budget per run [s]</source>
        <translation>Zeitbudget pro Lauf [s]</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>Kraftauswertungen</translation>
    </message>
    <message>
        <source>run time (median, band q1–q3)</source>
        <translation>Laufzeit (Median, Band q1–q3)</translation>
    </message>
    <message>
        <source>The cost of a run on the left panel: the force evaluations it took (a count: the same on every machine and every run), or its run time, the median over the timed runs with a band from q1 to q3 (on a busy machine a curve can zigzag backwards)</source>
        <translation>Der Aufwand eines Laufs im linken Feld: die Zahl seiner Kraftauswertungen (auf jedem Rechner und in jedem Lauf gleich) oder seine Laufzeit, der Median über die gemessenen Läufe mit einem Band von q1 bis q3 (auf einem ausgelasteten Rechner kann eine Kurve zurückspringen)</translation>
    </message>
    <message>
        <source>Cost axis</source>
        <translation>Aufwandsachse</translation>
    </message>
    <message>
        <source>max position error [m]</source>
        <translation>max. Positionsfehler [m]</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>run time [s] (median, band q1–q3)</source>
        <translation>Laufzeit [s] (Median, Band q1–q3)</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>Integrator</translation>
    </message>
    <message>
        <source>family</source>
        <translation>Familie</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>Schritte</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>Kraftausw.</translation>
    </message>
    <message>
        <source>run time q1 [s]</source>
        <translation>Laufzeit q1 [s]</translation>
    </message>
    <message>
        <source>median [s]</source>
        <translation>Median [s]</translation>
    </message>
    <message>
        <source>q3 [s]</source>
        <translation>q3 [s]</translation>
    </message>
    <message>
        <source>error at T [m]</source>
        <translation>Fehler bei T [m]</translation>
    </message>
    <message>
        <source>max error [m]</source>
        <translation>max. Fehler [m]</translation>
    </message>
    <message>
        <source>RMS error [m]</source>
        <translation>RMS-Fehler [m]</translation>
    </message>
    <message>
        <source>energy error [J]</source>
        <translation>Energiefehler [J]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>Status</translation>
    </message>
    <message>
        <source>Reference: %1 (its own error about %2 m). Run time: median of %3 timed runs per point, band q1–q3.</source>
        <translation>Referenz: %1 (ihr eigener Fehler etwa %2 m). Laufzeit: Median von %3 gemessenen Läufen pro Punkt, Band q1–q3.</translation>
    </message>
    <message>
        <source> %1: order %2 (RMS %3).</source>
        <translation> %1: Ordnung %2 (RMS %3).</translation>
    </message>
    <message>
        <source> q1–q3</source>
        <translation> q1–q3</translation>
    </message>
    <message>
        <source>fastest of its family</source>
        <translation>schnellstes seiner Familie</translation>
    </message>
</context>
<context>
    <name>simcore</name>
    <message>
        <source>structural spring stiffness KS, per spring (scaling=physical: at the reference resolution; a 2D chain keeps k L0, a 3D membrane keeps k)</source>
        <translation>Steifigkeit KS der Strukturfedern, pro Feder (scaling=physical: bei der Referenzauflösung; eine 2D-Kette behält k L0, eine 3D-Membran behält k)</translation>
    </message>
    <message>
        <source>structural spring damping KD, per spring; scales like KS</source>
        <translation>Dämpfung KD der Strukturfedern, pro Feder; skaliert wie KS</translation>
    </message>
    <message>
        <source>radius and shear spring stiffness RKS, per spring (scaling=physical: at the reference resolution; in parallel, k times count stays fixed)</source>
        <translation>Steifigkeit RKS der Radial- und Scherfedern, pro Feder (scaling=physical: bei der Referenzauflösung; parallel geschaltet bleibt k mal Anzahl fest)</translation>
    </message>
    <message>
        <source>radius and shear spring damping RKD, per spring; scales like RKS</source>
        <translation>Dämpfung RKD der Radial- und Scherfedern, pro Feder; skaliert wie RKS</translation>
    </message>
    <message>
        <source>gas constant nRT of each closed layer (PRESSURE): P = nRT / V</source>
        <translation>Gaskonstante nRT jeder geschlossenen Schicht (PRESSURE): P = nRT / V</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the inner layer (defaults to pressure)</source>
        <translation>nRT des von der inneren Schicht eingeschlossenen Gases (Standard: pressure)</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the outer layer (defaults to pressure)</source>
        <translation>nRT des von der äußeren Schicht eingeschlossenen Gases (Standard: pressure)</translation>
    </message>
    <message>
        <source>particle mass MASS (scaling=physical: at the reference resolution; each layer keeps its total)</source>
        <translation>Teilchenmasse MASS (scaling=physical: bei der Referenzauflösung; jede Schicht behält ihre Gesamtmasse)</translation>
    </message>
    <message>
        <source>inner-layer particle mass (defaults to mass; scaled like mass): real inertia, not scaled gravity</source>
        <translation>Teilchenmasse der inneren Schicht (Standard: mass; skaliert wie mass): echte Trägheit, keine skalierte Schwerkraft</translation>
    </message>
    <message>
        <source>outer-layer particle mass (defaults to mass; scaled like mass)</source>
        <translation>Teilchenmasse der äußeren Schicht (Standard: mass; skaliert wie mass)</translation>
    </message>
    <message>
        <source>gravitational acceleration, pointing along -y</source>
        <translation>Fallbeschleunigung, entlang -y gerichtet</translation>
    </message>
    <message>
        <source>half-size of the collision box (floor, ceiling, walls), centred on the body&apos;s start</source>
        <translation>halbe Kantenlänge der Kollisionsbox (Boden, Decke, Wände), um den Startort des Körpers zentriert</translation>
    </message>
    <message>
        <source>contact model: 0 = force (smooth penalty force inside the ODE, in the energy ledger), 1 = projection (the thesis program: put back and reflect after the step)</source>
        <translation>Kontaktmodell: 0 = force (glatte Straf-Kraft in der Differentialgleichung, in der Energiebilanz), 1 = projection (das Programm der Diplomarbeit: nach dem Schritt zurücksetzen und spiegeln)</translation>
    </message>
    <message>
        <source>coefficient of restitution e at the box walls: a particle hitting at contact_speed rebounds at e times its speed (projection: v_n becomes -e*v_n)</source>
        <translation>Stoßzahl e an den Wänden der Box: ein Teilchen, das mit contact_speed aufprallt, springt mit dem e-fachen seiner Geschwindigkeit zurück (projection: v_n wird -e*v_n)</translation>
    </message>
    <message>
        <source>k of the contact potential U = k d^4/4 per particle at a wall (d: penetration) and of the layer barrier (scaling=physical: at the reference resolution, scaled like mass)</source>
        <translation>k des Kontaktpotentials U = k d^4/4 pro Teilchen an einer Wand (d: Eindringtiefe) und der Schichtbarriere (scaling=physical: bei der Referenzauflösung, skaliert wie mass)</translation>
    </message>
    <message>
        <source>impact speed at which the contact damping gives exactly the restitution e</source>
        <translation>Aufprallgeschwindigkeit, bei der die Kontaktdämpfung genau die Stoßzahl e ergibt</translation>
    </message>
    <message>
        <source>wall friction: Coulomb coefficient mu (force); tangential velocity fraction removed (projection)</source>
        <translation>Wandreibung: Coulomb-Koeffizient mu (force); entzogener Anteil der Tangentialgeschwindigkeit (projection)</translation>
    </message>
    <message>
        <source>slip speed below which Coulomb friction is smoothed (regularised) [force contact]</source>
        <translation>Gleitgeschwindigkeit, unter der die Coulomb-Reibung geglättet (regularisiert) wird [Kontakt force]</translation>
    </message>
    <message>
        <source>mouse spring stiffness (MKS)</source>
        <translation>Steifigkeit der Mausfeder (MKS)</translation>
    </message>
    <message>
        <source>mouse spring damping (MKD)</source>
        <translation>Dämpfung der Mausfeder (MKD)</translation>
    </message>
    <message>
        <source>rest length of the mouse spring</source>
        <translation>Ruhelänge der Mausfeder</translation>
    </message>
    <message>
        <source>time step DT of fixed-step integrators (initial step of adaptive ones)</source>
        <translation>Zeitschritt DT der Integratoren mit fester Schrittweite (Anfangsschritt der adaptiven)</translation>
    </message>
    <message>
        <source>xpbd: substeps per step DT, one constraint iteration each (Macklin et al. 2019, small steps)</source>
        <translation>xpbd: Teilschritte pro Schritt DT, je eine Iteration der Nebenbedingungen (Macklin u. a. 2019, kleine Schritte)</translation>
    </message>
    <message>
        <source>what mass, ks, kd, rks, rkd and contact_stiffness mean when the mesh is refined: 0 = physical (the values hold at the scene&apos;s default resolution and the body keeps its totals and material constants), 1 = thesis (per particle and per spring at every resolution)</source>
        <translation>was mass, ks, kd, rks, rkd und contact_stiffness bedeuten, wenn das Netz verfeinert wird: 0 = physical (die Werte gelten bei der Standardauflösung der Szene, und der Körper behält seine Gesamtgrößen und Materialkonstanten), 1 = thesis (pro Teilchen und pro Feder bei jeder Auflösung)</translation>
    </message>
    <message>
        <source>particles per layer of the 2D ring</source>
        <translation>Teilchen pro Schicht des 2D-Rings</translation>
    </message>
    <message>
        <source>subdivision level L of the octahedron sphere: 4*4^L+2 particles per layer</source>
        <translation>Unterteilungsstufe L der Oktaederkugel: 4*4^L+2 Teilchen pro Schicht</translation>
    </message>
    <message>
        <source>meridians of the lat/long sphere</source>
        <translation>Meridiane der Längen-/Breitenkugel</translation>
    </message>
    <message>
        <source>latitude bands of the lat/long sphere (pole to pole)</source>
        <translation>Breitenbänder der Längen-/Breitenkugel (von Pol zu Pol)</translation>
    </message>
    <message>
        <source>rest radius of the inner layer (must be below radius_outer)</source>
        <translation>Ruheradius der inneren Schicht (muss unter radius_outer liegen)</translation>
    </message>
    <message>
        <source>rest radius of the outer layer</source>
        <translation>Ruheradius der äußeren Schicht</translation>
    </message>
    <message>
        <source>rest length of the 1D spring</source>
        <translation>Ruhelänge der 1D-Feder</translation>
    </message>
    <message>
        <source>distance between the two particles at the start (the spring hangs along -y)</source>
        <translation>Abstand der beiden Teilchen zu Beginn (die Feder hängt entlang -y)</translation>
    </message>
    <message>
        <source>1: the top particle is fixed in space (thesis fig. 7); 0: both particles move</source>
        <translation>1: das obere Teilchen ist im Raum fest (Diplomarbeit Abb. 7); 0: beide Teilchen bewegen sich</translation>
    </message>
    <message>
        <source>amplitude of a seeded random displacement of the start positions (breaks symmetry)</source>
        <translation>Amplitude einer zufälligen Verschiebung der Startpositionen mit festem Startwert (bricht die Symmetrie)</translation>
    </message>
    <message>
        <source>seed of the start perturbation</source>
        <translation>Startwert (Seed) der Startstörung</translation>
    </message>
    <message>
        <source>1D: two masses on one spring hanging along -y, the top one fixed (thesis fig. 7)</source>
        <translation>1D: zwei Massen an einer Feder, entlang -y hängend, die obere fest (Diplomarbeit Abb. 7)</translation>
    </message>
    <message>
        <source>2D: two concentric gas-filled rings joined by radius and shear springs (thesis 3.4)</source>
        <translation>2D: zwei konzentrische gasgefüllte Ringe, durch Radial- und Scherfedern verbunden (Diplomarbeit 3.4)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled spheres, subdivided octahedron (thesis 3.5.2)</source>
        <translation>3D: zwei konzentrische gasgefüllte Kugeln, unterteiltes Oktaeder (Diplomarbeit 3.5.2)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled lat/long spheres, the non-uniform sphere (thesis 3.5.1)</source>
        <translation>3D: zwei konzentrische gasgefüllte Längen-/Breitenkugeln, die ungleichmäßige Kugel (Diplomarbeit 3.5.1)</translation>
    </message>
    <message>
        <source>explicit Euler: x and v both from the old state (thesis eq. 22)</source>
        <translation>explizites Euler-Verfahren: x und v beide aus dem alten Zustand (Diplomarbeit Gl. 22)</translation>
    </message>
    <message>
        <source>the thesis&apos;s midpoint (eq. 31-33), i.e. Heun&apos;s RK2: two force evaluations</source>
        <translation>das Mittelpunktverfahren der Diplomarbeit (Gl. 31-33), d. h. Heuns RK2: zwei Kraftauswertungen</translation>
    </message>
    <message>
        <source>classical Runge-Kutta 4 (eq. 35-40): four force evaluations</source>
        <translation>klassisches Runge-Kutta 4 (Gl. 35-40): vier Kraftauswertungen</translation>
    </message>
    <message>
        <source>semi-implicit Euler: v from the old forces, then x from the new v</source>
        <translation>halbimplizites Euler-Verfahren: v aus den alten Kräften, dann x aus dem neuen v</translation>
    </message>
    <message>
        <source>velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)</source>
        <translation>Geschwindigkeits-Verlet (Ordnung 1 bei eingeschalteter Dämpfung: die Dämpfung wird mit der Geschwindigkeit im halben Schritt genommen)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 4th-order composition of velocity Verlet: 3 substeps (one backwards), 4 force evaluations (order 1 with damping)</source>
        <translation>Yoshidas Komposition 4. Ordnung aus Geschwindigkeits-Verlet: 3 Teilschritte (einer rückwärts), 4 Kraftauswertungen (Ordnung 1 mit Dämpfung)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 8th-order composition of velocity Verlet (solution D): 15 substeps, 16 force evaluations (order 1 with damping)</source>
        <translation>Yoshidas Komposition 8. Ordnung aus Geschwindigkeits-Verlet (Lösung D): 15 Teilschritte, 16 Kraftauswertungen (Ordnung 1 mit Dämpfung)</translation>
    </message>
    <message>
        <source>Dormand-Prince 5(4): adaptive step from atol/rtol, embedded error estimate every step</source>
        <translation>Dormand-Prince 5(4): adaptiver Schritt aus atol/rtol, eingebettete Fehlerschätzung bei jedem Schritt</translation>
    </message>
    <message>
        <source>linearised backward Euler (Baraff-Witkin 1998): spring and gas Jacobians, matrix-free CG</source>
        <translation>linearisiertes Rückwärts-Euler (Baraff-Witkin 1998): Jacobi-Matrizen von Federn und Gas, matrixfreies CG</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order BDF 1-5: Newton, matrix-free GMRES on the analytic Jacobian, implicit-euler&apos;s solve as preconditioner; adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, BDF variabler Ordnung 1-5: Newton, matrixfreies GMRES mit der analytischen Jacobi-Matrix, der Löser von implicit-euler als Vorkonditionierer; adaptiv aus atol/rtol</translation>
    </message>
    <message>
        <source>extended position-based dynamics (Macklin et al. 2016, small steps 2019): springs as compliant distance constraints, `substeps` substeps of one iteration per step</source>
        <translation>erweiterte positionsbasierte Dynamik (Macklin u. a. 2016, kleine Schritte 2019): Federn als nachgiebige Abstandsbedingungen, `substeps` Teilschritte mit je einer Iteration pro Schritt</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order Adams-Moulton 1-12 with fixed-point iteration (non-stiff); adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, Adams-Moulton variabler Ordnung 1-12 mit Fixpunktiteration (nicht steif); adaptiv aus atol/rtol</translation>
    </message>
</context>
</TS>
