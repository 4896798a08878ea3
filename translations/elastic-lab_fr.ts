<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="fr">
<context>
    <name>FailureText</name>
    <message>
        <source>the inner layer</source>
        <translation>la couche intérieure</translation>
    </message>
    <message>
        <source>the outer layer</source>
        <translation>la couche extérieure</translation>
    </message>
    <message>
        <source>the layer</source>
        <translation>la couche</translation>
    </message>
    <message>
        <source>%1 turned inside out (its area is %2, rest %3)</source>
        <translation>%1 s’est retournée (son aire vaut %2, au repos %3)</translation>
    </message>
    <message>
        <source>%1 turned inside out (its volume is %2, rest %3)</source>
        <translation>%1 s’est retournée (son volume vaut %2, au repos %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its area is %2, rest %3)</source>
        <translation>%1 s’est effondrée (son aire vaut %2, au repos %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its volume is %2, rest %3)</source>
        <translation>%1 s’est effondrée (son volume vaut %2, au repos %3)</translation>
    </message>
    <message>
        <source>body %1: %2</source>
        <translation>corps %1 : %2</translation>
    </message>
    <message>
        <source>the state became non-finite (NaN or infinity): the step is far too large for these forces</source>
        <translation>l’état n’est plus fini (NaN ou infini) : le pas est bien trop grand pour ces forces</translation>
    </message>
    <message>
        <source>rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too stiff or singular)</source>
        <translation>rk45 : le pas est tombé sous le pas minimal ; la tolérance ne peut pas être tenue (le système est trop raide ou singulier)</translation>
    </message>
    <message>
        <source>implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is not positive definite at this step (the body is too deformed or the step too large)</source>
        <translation>implicit-euler : la résolution linéaire (gradient conjugué) n’a pas convergé ; le système linéarisé n’est pas défini positif à ce pas (le corps est trop déformé ou le pas trop grand)</translation>
    </message>
    <message>
        <source>runaway velocity: a particle moves %1 m/s, farther than the whole box in one step</source>
        <translation>vitesse emballée : une particule va à %1 m/s, plus loin que toute la boîte en un pas</translation>
    </message>
    <message>
        <source>runaway energy: kinetic + elastic energy %1 J exceeds %2 J (%3 × the body&apos;s energy scale)</source>
        <translation>énergie emballée : l’énergie cinétique + élastique, %1 J, dépasse %2 J (%3 × l’échelle d’énergie du corps)</translation>
    </message>
    <message>
        <source>the state is no longer finite (particle %1)</source>
        <translation>l’état n’est plus fini (particule %1)</translation>
    </message>
    <message>
        <source>particle %1 reached a wall: the float path has no contact (use precision double)</source>
        <translation>la particule %1 a atteint une paroi : le calcul en float n’a pas de contact (choisissez la précision double)</translation>
    </message>
    <message>
        <source>body %1&apos;s outer layer passed through itself in a step of %2 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>la couche extérieure du corps %1 s’est traversée elle-même en un pas de %2 s : le pas est trop grand pour ce choc (un dt plus petit, ou un intégrateur adaptatif, qui divise un tel pas par deux)</translation>
    </message>
    <message>
        <source>bodies %1 and %2 intersect (their outer layers crossed) in a step of %3 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>les corps %1 et %2 s’interpénètrent (leurs couches extérieures se sont croisées) en un pas de %3 s : le pas est trop grand pour ce choc (un dt plus petit, ou un intégrateur adaptatif, qui divise un tel pas par deux)</translation>
    </message>
    <message>
        <source>exact spectrum, %1 eigenvalues</source>
        <translation>spectre exact, %1 valeurs propres</translation>
    </message>
    <message>
        <source>Arnoldi, %1 Ritz values of %2</source>
        <translation>Arnoldi, %1 valeurs de Ritz sur %2</translation>
    </message>
    <message>
        <source>exact step matrix</source>
        <translation>matrice de pas exacte</translation>
    </message>
    <message>
        <source>modes of M^-1 K</source>
        <translation>modes de M^-1 K</translation>
    </message>
    <message>
        <source>%1 chooses its own step: no DT limit from stability</source>
        <translation>%1 choisit son propre pas : la stabilité ne limite pas DT</translation>
    </message>
    <message>
        <source>%1 is stable at every DT on this body</source>
        <translation>%1 est stable à tout DT sur ce corps</translation>
    </message>
    <message>
        <source>%1 has no stable DT on this body: its undamped modes grow for every DT (%2)</source>
        <translation>%1 n’a aucun DT stable sur ce corps : ses modes non amortis croissent pour tout DT (%2)</translation>
    </message>
    <message>
        <source>%1 is stable up to DT = %2 s on this body (%3)</source>
        <translation>%1 est stable jusqu’à DT = %2 s sur ce corps (%3)</translation>
    </message>
    <message>
        <source>%1 has no stable step on this body&apos;s undamped modes (highest w = %2 rad/s): its energy grows for every dt, here by ~%3 per second; use dt &lt;= %4 s (growth below 1 per second) or another method</source>
        <translation>%1 n’a aucun pas stable sur les modes non amortis de ce corps (w le plus haut = %2 rad/s) : son énergie croît pour tout dt, ici d’environ %3 par seconde ; prenez dt &lt;= %4 s (croissance sous 1 par seconde) ou une autre méthode</translation>
    </message>
    <message>
        <source>dt = %1 s is above %2&apos;s largest stable step on this body, %3 s (linearised: %4; fastest |lambda| = %5 1/s); it will likely blow up (implicit-euler or rk45 will not)</source>
        <translation>dt = %1 s dépasse le plus grand pas stable de %2 sur ce corps, %3 s (linéarisé : %4 ; |lambda| le plus rapide = %5 1/s) ; la simulation va probablement exploser (implicit-euler ou rk45 non)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>solid</source>
        <translation>continu</translation>
    </message>
    <message>
        <source>hatched</source>
        <translation>hachuré</translation>
    </message>
    <message>
        <source>dotted</source>
        <translation>pointillé</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>Impossible d’ouvrir %1 : %2</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>Impossible d’écrire %1 : %2</translation>
    </message>
    <message>
        <source>the data was not written completely</source>
        <translation>les données n’ont pas été entièrement écrites</translation>
    </message>
    <message>
        <source>Could not encode %1 as %2</source>
        <translation>Impossible d’encoder %1 en %2</translation>
    </message>
    <message>
        <source>No plot to export</source>
        <translation>Aucun graphique à exporter</translation>
    </message>
    <message>
        <source>Could not encode %1</source>
        <translation>Impossible d’encoder %1</translation>
    </message>
    <message>
        <source>Three Verlet substeps (the middle one backwards): fourth order, and energy stays bounded like Verlet&apos;s; stable up to h·ω ≈ 1.57 on an undamped spring.</source>
        <translation>Trois sous-pas de Verlet (celui du milieu en arrière) : ordre quatre, et l’énergie reste bornée comme avec Verlet ; stable jusqu’à h·ω ≈ 1,57 sur un ressort non amorti.</translation>
    </message>
    <message>
        <source>Fifteen Verlet substeps: eighth order for undamped bodies, the error reaches round-off at moderate steps; 16 force evaluations a step.</source>
        <translation>Quinze sous-pas de Verlet : ordre huit pour les corps non amortis, l’erreur atteint l’arrondi dès des pas modérés ; 16 évaluations de force par pas.</translation>
    </message>
    <message>
        <source>Chooses its own step to meet a tolerance; the readout shows its error estimate.</source>
        <translation>Choisit lui-même son pas pour respecter une tolérance ; l’affichage montre son estimation d’erreur.</translation>
    </message>
    <message>
        <source>Stable at any DT (it damps instead of blowing up): the one to use for DT 0.3.</source>
        <translation>Stable à tout DT (il amortit au lieu d’exploser) : celui à utiliser pour DT 0,3.</translation>
    </message>
    <message>
        <source>A production stiff solver (SUNDIALS): wins where stiffness is damping (overdamped springs), not where it is fast oscillation, which it must still follow.</source>
        <translation>Un solveur raide de production (SUNDIALS) : gagnant quand la raideur vient de l’amortissement (ressorts suramortis), pas quand elle vient d’une oscillation rapide, qu’il doit quand même suivre.</translation>
    </message>
    <message>
        <source>A production non-stiff solver (SUNDIALS): high order, few force evaluations per step.</source>
        <translation>Un solveur non raide de production (SUNDIALS) : ordre élevé, peu d’évaluations de force par pas.</translation>
    </message>
    <message>
        <source>The game-physics way (Jolt, PhysX): stable at DT 1/60 on stiff springs, but it removes energy the body never lost; more substeps, less loss.</source>
        <translation>La méthode de la physique des jeux (Jolt, PhysX) : stable à DT 1/60 avec des ressorts raides, mais elle retire de l’énergie que le corps n’a jamais perdue ; plus de sous-pas, moins de perte.</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;A two-layer elastic body: particles joined by springs, with gas inside each closed layer. Drag the body with the mouse; change any parameter while it runs.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;Un corps élastique à deux couches : des particules reliées par des ressorts, avec du gaz dans chaque couche fermée. Faites glisser le corps avec la souris ; modifiez n’importe quel paramètre pendant la simulation.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;The model&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Particles&lt;/b&gt; carry mass; gravity pulls along −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Springs&lt;/b&gt; (Hooke + damping): &lt;i&gt;structural&lt;/i&gt; springs along each layer (KS, KD), &lt;i&gt;radius&lt;/i&gt; springs between paired inner and outer particles and &lt;i&gt;shear&lt;/i&gt; springs across them (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: each closed layer encloses gas with P = nRT / V, pushing outward on every edge (2D) or face (3D). V is the exact area or volume.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mouse spring&lt;/b&gt; (MKS, MKD) from the pointer to the grabbed particle.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Contact&lt;/b&gt; is a smooth force inside the equations of motion: a particle that sinks a depth d into a wall is pushed back by k d³ (contact energy k d⁴/4), damped so that one hitting at contact_speed rebounds with the restitution e, with smooth Coulomb friction, and a barrier of the same kind keeps the inner layer inside the outer one. contact = projection restores the thesis program instead, which puts a particle back and reverses its normal speed after each step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resolution&lt;/b&gt; (Scene dock): with scaling = physical the masses and spring constants hold at the scene&apos;s default mesh, and a finer mesh keeps the body&apos;s totals (layer mass, material stiffness), so it is the same body, only finer; scaling = thesis makes them per particle and per spring at every mesh. A finer body has faster modes and needs a smaller DT: the window offers one when a rebuild needs it.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;The plots show the energy book: kinetic + spring + gravity + gas + contact is the total; what damping and contact take out is &apos;removed&apos;. For an exact integrator, total + removed − work by the mouse stays constant; the readout&apos;s &lt;i&gt;energy drift&lt;/i&gt; is how far it is off.&lt;/p&gt;&lt;p&gt;View → &lt;b&gt;Energy bars&lt;/b&gt; shows the same book as bars, one per term, in the plot&apos;s colours, with the drift last. View → &lt;b&gt;P–V diagram&lt;/b&gt; shows each gas layer&apos;s pressure against its volume: the trail lies on the isotherm P = nRT / V, drawn dashed.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;Le modèle&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Les &lt;b&gt;particules&lt;/b&gt; portent la masse ; la pesanteur tire selon −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ressorts&lt;/b&gt; (Hooke + amortissement) : ressorts &lt;i&gt;structurels&lt;/i&gt; le long de chaque couche (KS, KD), ressorts &lt;i&gt;radiaux&lt;/i&gt; entre particules intérieures et extérieures appariées et ressorts de &lt;i&gt;cisaillement&lt;/i&gt; en travers (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gaz&lt;/b&gt; : chaque couche fermée enferme un gaz avec P = nRT / V, qui pousse vers l’extérieur sur chaque arête (2D) ou face (3D). V est l’aire ou le volume exact.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Ressort de souris&lt;/b&gt; (MKS, MKD) du pointeur à la particule saisie.&lt;/li&gt;&lt;li&gt;Le &lt;b&gt;contact&lt;/b&gt; est une force régulière dans les équations du mouvement : une particule qui s’enfonce d’une profondeur d dans une paroi est repoussée par k d³ (énergie de contact k d⁴/4), amortie de sorte qu’une particule arrivant à contact_speed rebondit avec le coefficient de restitution e, avec un frottement de Coulomb régularisé, et une barrière du même type maintient la couche intérieure dans l’extérieure. contact = projection rétablit à la place le programme du mémoire, qui replace une particule et inverse sa vitesse normale après chaque pas.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Résolution&lt;/b&gt; (dock Scène) : avec scaling = physical, masses et constantes de raideur valent pour le maillage par défaut de la scène, et un maillage plus fin conserve les totaux du corps (masse de couche, raideur du matériau) : c’est le même corps, en plus fin ; scaling = thesis en fait des valeurs par particule et par ressort pour tout maillage. Un corps plus fin a des modes plus rapides et demande un DT plus petit : la fenêtre en propose un quand une reconstruction l’exige.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Les graphiques montrent le bilan d’énergie : cinétique + ressort + pesanteur + gaz + contact forme le total ; ce que l’amortissement et le contact retirent est « retiré ». Pour un intégrateur exact, total + retiré − travail de la souris reste constant ; la &lt;i&gt;dérive d’énergie&lt;/i&gt; de l’affichage dit de combien il s’en écarte.&lt;/p&gt;&lt;p&gt;Affichage → &lt;b&gt;Barres d’énergie&lt;/b&gt; montre le même bilan en barres, une par terme, aux couleurs des graphiques, la dérive en dernier. Affichage → &lt;b&gt;Diagramme P–V&lt;/b&gt; montre la pression de chaque couche de gaz en fonction de son volume : la trace suit l’isotherme P = nRT / V, en tirets.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Integrators&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;name&lt;/th&gt;&lt;th&gt;order&lt;/th&gt;&lt;th&gt;what it does&lt;/th&gt;&lt;th&gt;in class&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;h3&gt;Intégrateurs&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;nom&lt;/th&gt;&lt;th&gt;ordre&lt;/th&gt;&lt;th&gt;ce qu’il fait&lt;/th&gt;&lt;th&gt;en classe&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Presets&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Préréglages&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Mouse&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Left-drag on the body: grab the nearest outer particle and pull it.&lt;/li&gt;&lt;li&gt;Left-drag elsewhere, or Shift+left-drag (3D): orbit. Right- or middle-drag: pan. Wheel: zoom. View → Reset view.&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Souris&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Glisser avec le bouton gauche sur le corps : saisir la particule extérieure la plus proche et la tirer.&lt;/li&gt;&lt;li&gt;Glisser à gauche ailleurs, ou Maj+glisser à gauche (3D) : tourner. Glisser avec le bouton droit ou du milieu : déplacer. Molette : zoomer. Affichage → Réinitialiser la vue.&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;More&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Plus&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>The GUI (docs/gui.md)</source>
        <translation>L’interface (docs/gui.md)</translation>
    </message>
    <message>
        <source>Architecture (docs/architecture.md)</source>
        <translation>Architecture (docs/architecture.md)</translation>
    </message>
    <message>
        <source>README</source>
        <translation>README</translation>
    </message>
    <message>
        <source>1. How large may DT be for Euler?</source>
        <translation>1. Quelle taille de DT pour Euler ?</translation>
    </message>
    <message>
        <source>2. Energy drift: Euler, midpoint, RK4</source>
        <translation>2. Dérive d’énergie : Euler, point milieu, RK4</translation>
    </message>
    <message>
        <source>3. A heavy inner layer: liquid motion</source>
        <translation>3. Une couche intérieure lourde : mouvement de liquide</translation>
    </message>
    <message>
        <source>4. A finer sphere needs a smaller DT</source>
        <translation>4. Une sphère plus fine demande un DT plus petit</translation>
    </message>
    <message>
        <source>5. Pressure and volume on the isotherm</source>
        <translation>5. Pression et volume sur l’isotherme</translation>
    </message>
    <message>
        <source>6. Restitution: a particle and a body</source>
        <translation>6. Restitution : une particule et un corps</translation>
    </message>
    <message>
        <source>7. Stiff springs: explicit against implicit</source>
        <translation>7. Ressorts raides : explicite contre implicite</translation>
    </message>
    <message>
        <source>8. Why symplectic? Energy over ten thousand periods</source>
        <translation>8. Pourquoi symplectique ? L’énergie sur dix mille périodes</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>Objectif</translation>
    </message>
    <message>
        <source>What to do</source>
        <translation>Que faire</translation>
    </message>
    <message>
        <source>What to look at</source>
        <translation>Quoi observer</translation>
    </message>
    <message>
        <source>The measured answer</source>
        <translation>La réponse mesurée</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Pourquoi</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Ressorts</translation>
    </message>
    <message>
        <source>Gas</source>
        <translation>Gaz</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masse</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Environnement</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Contact</translation>
    </message>
    <message>
        <source>Mouse spring</source>
        <translation>Ressort de souris</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Temps</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forme</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Départ</translation>
    </message>
    <message>
        <source>gas nRT</source>
        <translation>gaz nRT</translation>
    </message>
    <message>
        <source>gas nRT inner</source>
        <translation>gaz nRT intérieur</translation>
    </message>
    <message>
        <source>gas nRT outer</source>
        <translation>gaz nRT extérieur</translation>
    </message>
    <message>
        <source>Area per layer</source>
        <translation>Aire par couche</translation>
    </message>
    <message>
        <source>Volume per layer</source>
        <translation>Volume par couche</translation>
    </message>
    <message>
        <source>area [m²]</source>
        <translation>aire [m²]</translation>
    </message>
    <message>
        <source>volume [m³]</source>
        <translation>volume [m³]</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>intérieure</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>extérieure</translation>
    </message>
    <message>
        <source>Pressure per layer</source>
        <translation>Pression par couche</translation>
    </message>
    <message>
        <source>pressure [N/m]</source>
        <translation>pression [N/m]</translation>
    </message>
    <message>
        <source>pressure [Pa]</source>
        <translation>pression [Pa]</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Énergie</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>énergie [J]</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>cinétique</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>ressort</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>pesanteur</translation>
    </message>
    <message>
        <source>gas</source>
        <translation>gaz</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>contact</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>retiré</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>retiré par le contact</translation>
    </message>
    <message>
        <source>spring: structural</source>
        <translation>ressort : structurel</translation>
    </message>
    <message>
        <source>spring: radius</source>
        <translation>ressort : radial</translation>
    </message>
    <message>
        <source>spring: shear</source>
        <translation>ressort : cisaillement</translation>
    </message>
    <message>
        <source>mouse spring</source>
        <translation>ressort de souris</translation>
    </message>
    <message>
        <source>removed by damping</source>
        <translation>retiré par l’amortissement</translation>
    </message>
    <message>
        <source>removed by projection</source>
        <translation>retiré par la projection</translation>
    </message>
    <message>
        <source>drift (balance error)</source>
        <translation>dérive (erreur de bilan)</translation>
    </message>
    <message>
        <source>1D drop: two masses on a spring</source>
        <translation>Chute 1D : deux masses sur un ressort</translation>
    </message>
    <message>
        <source>Both masses fall, hit the floor and bounce; the spring oscillates (thesis fig. 7).</source>
        <translation>Les deux masses tombent, touchent le sol et rebondissent ; le ressort oscille (mémoire, fig. 7).</translation>
    </message>
    <message>
        <source>1D hanging spring</source>
        <translation>Ressort suspendu 1D</translation>
    </message>
    <message>
        <source>The top mass is fixed; the lower one oscillates around the stretched rest length.</source>
        <translation>La masse du haut est fixe ; celle du bas oscille autour de la longueur au repos étirée.</translation>
    </message>
    <message>
        <source>2D ring</source>
        <translation>Anneau 2D</translation>
    </message>
    <message>
        <source>Two gas-filled rings joined by radius and shear springs drop onto the floor (thesis 3.4).</source>
        <translation>Deux anneaux remplis de gaz, reliés par des ressorts radiaux et de cisaillement, tombent sur le sol (mémoire 3.4).</translation>
    </message>
    <message>
        <source>3D sphere</source>
        <translation>Sphère 3D</translation>
    </message>
    <message>
        <source>Two gas-filled spheres (subdivided octahedron) drop and bounce (thesis 3.5.2).</source>
        <translation>Deux sphères remplies de gaz (octaèdre subdivisé) tombent et rebondissent (mémoire 3.5.2).</translation>
    </message>
    <message>
        <source>3D lat/long sphere (non-uniform)</source>
        <translation>Sphère 3D en longitude/latitude (non uniforme)</translation>
    </message>
    <message>
        <source>The lat/long sphere: particles crowd at the poles, so the body is not uniform (thesis 3.5.1).</source>
        <translation>La sphère en longitude/latitude : les particules se serrent aux pôles, le corps n’est donc pas uniforme (mémoire 3.5.1).</translation>
    </message>
    <message>
        <source>Heavy inner layer (non-uniform density)</source>
        <translation>Couche intérieure lourde (densité non uniforme)</translation>
    </message>
    <message>
        <source>The inner layer is five times heavier: it sinks inside the outer one and the body lands bottom-heavy (thesis 8.1).</source>
        <translation>La couche intérieure est cinq fois plus lourde : elle s’enfonce dans l’extérieure et le corps atterrit lesté vers le bas (mémoire 8.1).</translation>
    </message>
    <message>
        <source>Liquid motion and inertia</source>
        <translation>Mouvement de liquide et inertie</translation>
    </message>
    <message>
        <source>Inner and outer layers pushed in opposite directions (3 m/s), without gravity and with soft, lightly damped radius and shear springs: the inner layer sloshes inside the outer one like a liquid (thesis fig. 47).</source>
        <translation>Couches intérieure et extérieure poussées en sens opposés (3 m/s), sans pesanteur et avec des ressorts radiaux et de cisaillement souples et peu amortis : la couche intérieure ballotte dans l’extérieure comme un liquide (mémoire, fig. 47).</translation>
    </message>
    <message>
        <source>Stability experiment, DT = %1 s</source>
        <translation>Expérience de stabilité, DT = %1 s</translation>
    </message>
    <message>
        <source>Euler, midpoint and RK4 from the same start at DT = %1 s (thesis 7.2.2, figs. 41-43). Watch which one blows up.</source>
        <translation>Euler, point milieu et RK4 depuis le même départ à DT = %1 s (mémoire 7.2.2, fig. 41-43). Observez lequel explose.</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>illimité</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>Cheapest and least stable: on an undamped spring it gains energy at every DT. On the two-layer ring it holds for 2 s up to DT %1 s (measured).</source>
        <translation>Le moins cher et le moins stable : sur un ressort non amorti, il gagne de l’énergie à chaque DT. Sur l’anneau à deux couches, il tient 2 s jusqu’à DT %1 s (mesuré).</translation>
    </message>
    <message>
        <source>Two force evaluations per step, second order; on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03.</source>
        <translation>Deux évaluations de force par pas, ordre deux ; sur l’anneau à deux couches, il tient 2 s jusqu’à DT %1 s (mesuré), il échoue donc au 0,03 du mémoire.</translation>
    </message>
    <message>
        <source>Four evaluations, fourth order; stable up to h·ω ≈ 2.8: on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03 and 0.3.</source>
        <translation>Quatre évaluations, ordre quatre ; stable jusqu’à h·ω ≈ 2,8 : sur l’anneau à deux couches, il tient 2 s jusqu’à DT %1 s (mesuré), il échoue donc aux 0,03 et 0,3 du mémoire.</translation>
    </message>
    <message>
        <source>Same cost as Euler, but energy stays bounded on an undamped spring (h·ω &amp;lt; 2).</source>
        <translation>Même coût qu’Euler, mais l’énergie reste bornée sur un ressort non amorti (h·ω &amp;lt; 2).</translation>
    </message>
    <message>
        <source>Velocity Verlet: time-reversible, good long-run energy behaviour. Second order without damping; with the dampers on (every scene here) its damping sees the half-step velocity and it is first order: the fitted order on the damped spring is %1 (measured).</source>
        <translation>Verlet vitesse : réversible en temps, bon comportement de l’énergie sur la durée. Ordre deux sans amortissement ; avec les amortisseurs actifs (toutes les scènes ici), son amortissement voit la vitesse du demi-pas et il est d’ordre un : l’ordre ajusté sur le ressort amorti est %1 (mesuré).</translation>
    </message>
    <message>
        <source>2 (1 damped)</source>
        <translation>2 (1 amorti)</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Lessons&lt;/b&gt; menu (or Help → Experiments): %1 guided experiments, each set up in one click, with what to change, what to look at and the answer measured with elastic-lab-cli; the Lesson dock shows what each answer expects beside what your run gives.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Menu &lt;b&gt;Leçons&lt;/b&gt; (ou Aide → Expériences) : %1 expériences guidées, chacune préparée en un clic, avec ce qu’il faut changer, ce qu’il faut observer et la réponse mesurée avec elastic-lab-cli ; le dock Leçon montre ce que chaque réponse attend à côté de ce que donne votre simulation.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Lessons &gt; Lesson texts explains what to do.</source>
        <translation>Leçons &gt; Textes des leçons explique quoi faire.</translation>
    </message>
    <message>
        <source>height of particle %1</source>
        <translation>hauteur de la particule %1</translation>
    </message>
    <message>
        <source>speed of particle %1</source>
        <translation>vitesse de la particule %1</translation>
    </message>
    <message>
        <source>height of the inner layer&apos;s centre</source>
        <translation>hauteur du centre de la couche intérieure</translation>
    </message>
    <message>
        <source>height of the outer layer&apos;s centre</source>
        <translation>hauteur du centre de la couche extérieure</translation>
    </message>
    <message>
        <source>centre-of-mass height</source>
        <translation>hauteur du centre de masse</translation>
    </message>
    <message>
        <source>centre-of-mass speed</source>
        <translation>vitesse du centre de masse</translation>
    </message>
    <message>
        <source>layers&apos; separation</source>
        <translation>écart entre les couches</translation>
    </message>
    <message>
        <source>9. Two balloons collide: momentum and energy</source>
        <translation>9. Deux ballons se heurtent : quantité de mouvement et énergie</translation>
    </message>
    <message>
        <source>10. A soft stack: how the bottom body carries the others</source>
        <translation>10. Une pile molle : comment le corps du bas porte les autres</translation>
    </message>
</context>
<context>
    <name>WorldExport</name>
    <message>
        <source>No run of several bodies to export</source>
        <translation>Aucune simulation à plusieurs corps à exporter</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Exporter les données</translation>
    </message>
    <message>
        <source>CSV of several bodies, comma and decimal point (*.csv)</source>
        <translation>CSV à plusieurs corps, virgule et point décimal (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %1 rows of the world to %2</source>
        <translation>%1 lignes du monde écrites dans %2</translation>
    </message>
</context>
<context>
    <name>elui::BodiesDock</name>
    <message>
        <source>Bodies</source>
        <translation>Corps</translation>
    </message>
    <message>
        <source>The bodies of the scene, total momentum and the smallest gap, with their curves against simulated time</source>
        <translation>Les corps de la scène, la quantité de mouvement totale et le plus petit écart, avec leurs courbes en fonction du temps simulé</translation>
    </message>
    <message>
        <source>This dock is for scenes of several bodies: Presets &gt; Several bodies, or a scene file of several bodies.</source>
        <translation>Ce panneau est destiné aux scènes à plusieurs corps : Préréglages &gt; Plusieurs corps, ou un fichier de scène à plusieurs corps.</translation>
    </message>
    <message>
        <source>body</source>
        <translation>corps</translation>
    </message>
    <message>
        <source>mass [kg]</source>
        <translation>masse [kg]</translation>
    </message>
    <message>
        <source>centre [m]</source>
        <translation>centre [m]</translation>
    </message>
    <message>
        <source>velocity [m/s]</source>
        <translation>vitesse [m/s]</translation>
    </message>
    <message>
        <source>volume in/out</source>
        <translation>volume int./ext.</translation>
    </message>
    <message>
        <source>pressure in/out</source>
        <translation>pression int./ext.</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>Quantité de mouvement totale</translation>
    </message>
    <message>
        <source>min_gap</source>
        <translation>min_gap</translation>
    </message>
    <message>
        <source>Volume per body and layer</source>
        <translation>Volume par corps et par couche</translation>
    </message>
    <message>
        <source>Pressure per body and layer</source>
        <translation>Pression par corps et par couche</translation>
    </message>
    <message>
        <source>gap [m]</source>
        <translation>écart [m]</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>volume</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>pression</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>ring2d: particles per layer; sphere3d: subdivisions; sphere3d-latlong: slices</source>
        <translation>ring2d : particules par couche ; sphere3d : subdivisions ; sphere3d-latlong : tranches</translation>
    </message>
    <message>
        <source>kind, level</source>
        <translation>type, niveau</translation>
    </message>
    <message>
        <source>where [m]</source>
        <translation>où [m]</translation>
    </message>
    <message>
        <source>how fast [m/s]</source>
        <translation>à quelle vitesse [m/s]</translation>
    </message>
    <message>
        <source>Add body</source>
        <translation>Ajouter un corps</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>Retirer la sélection</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>intérieur</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>extérieur</translation>
    </message>
    <message>
        <source> (body%1 with itself)</source>
        <translation> (body%1 avec lui-même)</translation>
    </message>
    <message>
        <source> (body%1 and body%2)</source>
        <translation> (body%1 et body%2)</translation>
    </message>
    <message>
        <source>beyond %1 m (nothing that close)</source>
        <translation>au-delà de %1 m (rien d&apos;aussi proche)</translation>
    </message>
    <message>
        <source>&lt;b&gt;momentum&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;angular momentum&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contact between bodies&lt;/b&gt; %4 J, %5 pairs in the skin</source>
        <translation>&lt;b&gt;quantité de mouvement&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;moment cinétique&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contact entre corps&lt;/b&gt; %4 J, %5 paires dans la peau</translation>
    </message>
    <message>
        <source>%1: not a number</source>
        <translation>%1 : pas un nombre</translation>
    </message>
    <message>
        <source>Choose a body in the list first.</source>
        <translation>Choisissez d&apos;abord un corps dans la liste.</translation>
    </message>
    <message>
        <source>A world keeps at least one body.</source>
        <translation>Un monde garde au moins un corps.</translation>
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
        <translation>Côte à côte</translation>
    </message>
    <message>
        <source>Run the same scene with up to three integrators from the same start state. Parameter edits and mouse drags go to all of them.</source>
        <translation>Simuler la même scène avec jusqu’à trois intégrateurs depuis le même état initial. Les modifications de paramètres et les glissements de souris s’appliquent à tous.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(aucun)</translation>
    </message>
    <message>
        <source>View %1</source>
        <translation>Vue %1</translation>
    </message>
    <message>
        <source>The integrator of the first view</source>
        <translation>L’intégrateur de la première vue</translation>
    </message>
    <message>
        <source>The integrator of this view, or none</source>
        <translation>L’intégrateur de cette vue, ou aucun</translation>
    </message>
    <message>
        <source>%1 s, common to every view (set it in the Run dock)</source>
        <translation>%1 s, commun à toutes les vues (à régler dans le dock Simulation)</translation>
    </message>
    <message>
        <source>DT</source>
        <translation>DT</translation>
    </message>
    <message>
        <source>Start the views side by side from the current start state</source>
        <translation>Démarrer les vues côte à côte depuis l’état initial actuel</translation>
    </message>
    <message>
        <source>Keep the views as they are</source>
        <translation>Garder les vues telles quelles</translation>
    </message>
</context>
<context>
    <name>elui::ConservationDialog</name>
    <message>
        <source>Long-time energy</source>
        <translation>Énergie sur la durée</translation>
    </message>
    <message>
        <source>Run length in periods of the body&apos;s fastest mode (damping switched off)</source>
        <translation>Durée en périodes du mode le plus rapide du corps (amortissement coupé)</translation>
    </message>
    <message>
        <source>The fixed step of every run [s]</source>
        <translation>Le pas fixe de chaque simulation [s]</translation>
    </message>
    <message>
        <source>float: the float build of the 1D spring, where round-off shows as a random walk</source>
        <translation>float : la version float du ressort 1D, où l’arrondi apparaît comme une marche aléatoire</translation>
    </message>
    <message>
        <source>Periods</source>
        <translation>Périodes</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Précision</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|energy error| envelope [J]</source>
        <translation>enveloppe de |erreur d’énergie| [J]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>intégrateur</translation>
    </message>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation>intervalle à 95 %</translation>
    </message>
    <message>
        <source>class</source>
        <translation>classe</translation>
    </message>
    <message>
        <source>final |ΔE| [J]</source>
        <translation>|ΔE| final [J]</translation>
    </message>
    <message>
        <source>relative</source>
        <translation>relatif</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <source>status</source>
        <translation>état</translation>
    </message>
    <message>
        <source>%1: %2, α = %3</source>
        <translation>%1 : %2, α = %3</translation>
    </message>
    <message>
        <source>%1: failed</source>
        <translation>%1 : échec</translation>
    </message>
    <message>
        <source>slope 1/2 (random walk)</source>
        <translation>pente 1/2 (marche aléatoire)</translation>
    </message>
    <message>
        <source>slope 1 (drift)</source>
        <translation>pente 1 (dérive)</translation>
    </message>
    <message>
        <source>The study did not run: %1</source>
        <translation>L’étude n’a pas tourné : %1</translation>
    </message>
    <message>
        <source>Undamped (%1). Fastest mode ω = %2 rad/s, period %3 s; DT = %4 s (h·ω = %5); %6 periods = %7 s. α: slope of log |ΔE| against log t from 10 periods on; bounded &lt; 0.25 ≤ random walk &lt; 0.75 ≤ drift.</source>
        <translation>Non amorti (%1). Mode le plus rapide ω = %2 rad/s, période %3 s ; DT = %4 s (h·ω = %5) ; %6 périodes = %7 s. α : pente de log |ΔE| en fonction de log t à partir de 10 périodes ; borné &lt; 0,25 ≤ marche aléatoire &lt; 0,75 ≤ dérive.</translation>
    </message>
</context>
<context>
    <name>elui::EnergyBarsDock</name>
    <message>
        <source>Energy bars</source>
        <translation>Barres d’énergie</translation>
    </message>
    <message>
        <source>Each part of the energy as a bar, named on the axis; the values are in the Run dock&apos;s readout</source>
        <translation>Chaque part de l’énergie en barre, nommée sur l’axe ; les valeurs sont dans l’affichage du dock Simulation</translation>
    </message>
    <message>
        <source>Energy book</source>
        <translation>Bilan d’énergie</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>énergie [J]</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
total %2, at the start %3</source>
        <translation>Énergie à t = %1 s
total %2, au départ %3</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
%2</source>
        <translation>Énergie à t = %1 s
%2</translation>
    </message>
</context>
<context>
    <name>elui::FailureBanner</name>
    <message>
        <source>Start again from the beginning with the step that ran through the failed stretch</source>
        <translation>Recommencer depuis le début avec le pas qui a traversé le passage en échec</translation>
    </message>
    <message>
        <source>Use implicit-euler and reset</source>
        <translation>Utiliser implicit-euler et réinitialiser</translation>
    </message>
    <message>
        <source>Start again with the implicit Euler integrator, which is stable at any time step</source>
        <translation>Recommencer avec l’intégrateur d’Euler implicite, stable pour tout pas de temps</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>Start again from the beginning with the same settings</source>
        <translation>Recommencer depuis le début avec les mêmes réglages</translation>
    </message>
    <message>
        <source>&lt;b&gt;The simulation blew up&lt;/b&gt; at t = %1 s (step %2): %3. The run is paused and shows the last good state.</source>
        <translation>&lt;b&gt;La simulation a explosé&lt;/b&gt; à t = %1 s (pas %2) : %3. La simulation est en pause et montre le dernier état valide.</translation>
    </message>
    <message>
        <source>Checking whether a smaller step survives the same stretch (a re-run at a quarter of DT, in the background)…</source>
        <translation>Vérification : un pas plus petit survit-il au même passage ? (nouvelle simulation au quart de DT, en arrière-plan)…</translation>
    </message>
    <message>
        <source>Try a smaller DT, a more stable integrator (rk4, or implicit-euler), softer springs or less pressure, then Reset.</source>
        <translation>Essayez un DT plus petit, un intégrateur plus stable (rk4 ou implicit-euler), des ressorts plus souples ou moins de pression, puis Réinitialiser.</translation>
    </message>
    <message>
        <source>Use DT = %1 s and reset</source>
        <translation>Utiliser DT = %1 s et réinitialiser</translation>
    </message>
    <message>
        <source>The body itself collapses — no step size will save it: run again from t = %1 s at a step of %2 s (%3), it fails at t = %4 s as well (%5). Change the body instead: lighter masses or less gravity, stiffer springs (ks, and the radial ones), more gas pressure, or more damping.</source>
        <translation>Le corps lui-même s’effondre — aucun pas de temps ne le sauvera : relancé depuis t = %1 s avec un pas de %2 s (%3), il échoue lui aussi à t = %4 s (%5). Changez plutôt le corps : des masses plus légères ou moins de pesanteur, des ressorts plus raides (ks, et les radiaux), plus de pression de gaz, ou plus d’amortissement.</translation>
    </message>
    <message>
        <source>The step was too large: run again from t = %1 s at a step of %2 s, the same stretch runs through t = %3 s. The linearised body agrees: %4.</source>
        <translation>Le pas était trop grand : relancé depuis t = %1 s avec un pas de %2 s, le même passage va jusqu’à t = %3 s. Le corps linéarisé le confirme : %4.</translation>
    </message>
</context>
<context>
    <name>elui::HelpDialog</name>
    <message>
        <source>Elastic Lab help</source>
        <translation>Aide d’Elastic Lab</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Aide</translation>
    </message>
    <message>
        <source>How to use Elastic Lab: the view, the docks, the integrators and the files</source>
        <translation>Comment utiliser Elastic Lab : la vue, les docks, les intégrateurs et les fichiers</translation>
    </message>
    <message>
        <source>Close the help</source>
        <translation>Fermer l’aide</translation>
    </message>
</context>
<context>
    <name>elui::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>Leçon</translation>
    </message>
    <message>
        <source>Run until t =</source>
        <translation>Simuler jusqu’à t =</translation>
    </message>
    <message>
        <source>Run as fast as possible and pause at this simulated time.</source>
        <translation>Simuler aussi vite que possible et s’arrêter à ce temps simulé.</translation>
    </message>
    <message>
        <source>Simulated time between Start and Stop (the first view&apos;s clock).</source>
        <translation>Temps simulé entre Départ et Arrêt (l’horloge de la première vue).</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Départ</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Zéro</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>réponse</translation>
    </message>
    <message>
        <source>expected</source>
        <translation>attendu</translation>
    </message>
    <message>
        <source>you got</source>
        <translation>obtenu</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Mesurer</translation>
    </message>
    <message>
        <source>Measure every answer on the parameters in use, as the lesson&apos;s elastic-lab-cli commands do (stability scans, weightless impacts, runs).</source>
        <translation>Mesurer chaque réponse avec les paramètres actuels, comme le font les commandes elastic-lab-cli de la leçon (balayages de stabilité, chocs sans pesanteur, simulations).</translation>
    </message>
    <message>
        <source>&lt;small&gt;you got: from your run, or &lt;i&gt;measured&lt;/i&gt; (Measure); green within the text&apos;s tolerance, amber off it&lt;/small&gt;</source>
        <translation>&lt;small&gt;obtenu : d’après votre simulation, ou &lt;i&gt;mesuré&lt;/i&gt; (Mesurer) ; vert dans la tolérance du texte, orangé hors de celle-ci&lt;/small&gt;</translation>
    </message>
    <message>
        <source>No lesson: choose one in the Lessons menu. Run until and the stopwatch work for any scene.</source>
        <translation>Aucune leçon : choisissez-en une dans le menu Leçons. « Simuler jusqu’à » et le chronomètre fonctionnent pour toute scène.</translation>
    </message>
    <message>
        <source>Stopwatch: &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>Chronomètre : &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Arrêt</translation>
    </message>
    <message>
        <source>read off your run</source>
        <translation>lu sur votre simulation</translation>
    </message>
    <message>
        <source>press Measure</source>
        <translation>appuyez sur Mesurer</translation>
    </message>
    <message>
        <source>measured on the parameters in use</source>
        <translation>mesuré avec les paramètres actuels</translation>
    </message>
    <message>
        <source>t = &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>t = &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1: energy drift &lt;b&gt;%2 J&lt;/b&gt;%3</source>
        <translation>%1 : dérive d’énergie &lt;b&gt;%2 J&lt;/b&gt;%3</translation>
    </message>
    <message>
        <source>, blew up at t = %1 s</source>
        <translation>, a explosé à t = %1 s</translation>
    </message>
    <message>
        <source>centre of mass: %1 m above the floor, vertical speed %2 m/s</source>
        <translation>centre de masse : %1 m au-dessus du sol, vitesse verticale %2 m/s</translation>
    </message>
    <message>
        <source>layer centres above the floor: inner %1 m, outer %2 m; the inner one sits &lt;b&gt;%3 m&lt;/b&gt; %4</source>
        <translation>centres des couches au-dessus du sol : intérieure %1 m, extérieure %2 m ; l’intérieure se trouve &lt;b&gt;%3 m&lt;/b&gt; %4</translation>
    </message>
    <message>
        <source>below</source>
        <translation>en dessous</translation>
    </message>
    <message>
        <source>above</source>
        <translation>au-dessus</translation>
    </message>
    <message>
        <source>centre of mass hit the floor at %1 m/s%2</source>
        <translation>le centre de masse a touché le sol à %1 m/s%2</translation>
    </message>
    <message>
        <source>, left it at %1 m/s (ratio %2)</source>
        <translation>, l’a quitté à %1 m/s (rapport %2)</translation>
    </message>
    <message>
        <source>lowest point %1 m above the floor%2</source>
        <translation>point le plus bas %1 m au-dessus du sol%2</translation>
    </message>
    <message>
        <source>lowest point %1 m into the floor (contact)%2</source>
        <translation>point le plus bas %1 m dans le sol (contact)%2</translation>
    </message>
    <message>
        <source>; last left the floor at t = %1 s</source>
        <translation>&#x202f;; a quitté le sol pour la dernière fois à t = %1 s</translation>
    </message>
    <message>
        <source>inner layer: %1 %2, pressure %3 %4</source>
        <translation>couche intérieure : %1 %2, pression %3 %4</translation>
    </message>
    <message>
        <source>measuring on the parameters in use…</source>
        <translation>mesure avec les paramètres actuels…</translation>
    </message>
    <message>
        <source>Run until a time, a stopwatch, and each answer of the lesson beside what your run gives</source>
        <translation>Simuler jusqu’à un instant, un chronomètre, et chaque réponse de la leçon à côté de ce que donne votre simulation</translation>
    </message>
    <message>
        <source>Run until this simulated time</source>
        <translation>Simuler jusqu’à ce temps simulé</translation>
    </message>
    <message>
        <source>The simulated time [s] at which Run until pauses</source>
        <translation>Le temps simulé [s] auquel « Simuler jusqu’à » s’arrête</translation>
    </message>
    <message>
        <source>Start or stop the stopwatch on the simulated clock</source>
        <translation>Démarrer ou arrêter le chronomètre sur l’horloge simulée</translation>
    </message>
    <message>
        <source>Set the stopwatch back to zero</source>
        <translation>Remettre le chronomètre à zéro</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; smallest gap %2 m</source>
        <translation>quantité de mouvement totale &lt;b&gt;%1 kg m/s&lt;/b&gt; ; plus petit écart %2 m</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; no gap below %2 m</source>
        <translation>quantité de mouvement totale &lt;b&gt;%1 kg m/s&lt;/b&gt; ; aucun écart sous %2 m</translation>
    </message>
    <message>
        <source>body%1: centre velocity %2 m/s, outer %3 %4 of %5 at rest</source>
        <translation>body%1 : vitesse du centre %2 m/s, %3 extérieur %4 sur %5 au repos</translation>
    </message>
    <message>
        <source>area</source>
        <translation>aire</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>volume</translation>
    </message>
</context>
<context>
    <name>elui::LessonsDialog</name>
    <message>
        <source>Experiments</source>
        <translation>Expériences</translation>
    </message>
    <message>
        <source>Short guided experiments: each sets up a scene, says what to change and what to look at, and gives the answer measured with elastic-lab-cli.</source>
        <translation>De courtes expériences guidées : chacune prépare une scène, dit ce qu’il faut changer et observer, et donne la réponse mesurée avec elastic-lab-cli.</translation>
    </message>
    <message>
        <source>The guided experiments; the arrow keys choose one, its text is beside the list</source>
        <translation>Les expériences guidées ; les flèches en choisissent une, son texte est à côté de la liste</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Expérience</translation>
    </message>
    <message>
        <source>What the chosen experiment sets up, what to change and what to look for</source>
        <translation>Ce que l’expérience choisie prépare, ce qu’il faut changer et observer</translation>
    </message>
    <message>
        <source>Set up this experiment</source>
        <translation>Préparer cette expérience</translation>
    </message>
    <message>
        <source>Set up the chosen experiment in the main window: its scene, parameters and docks</source>
        <translation>Préparer l’expérience choisie dans la fenêtre principale : sa scène, ses paramètres et ses docks</translation>
    </message>
    <message>
        <source>Close the experiments; the main window keeps its scene</source>
        <translation>Fermer les expériences ; la fenêtre principale garde sa scène</translation>
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
        <translation>&amp;Ouvrir une scène...</translation>
    </message>
    <message>
        <source>A scene file (.json): scene, parameters, integrator and, if saved, the exact state</source>
        <translation>Un fichier de scène (.json) : scène, paramètres, intégrateur et, s’il a été enregistré, l’état exact</translation>
    </message>
    <message>
        <source>&amp;Save scene</source>
        <translation>&amp;Enregistrer la scène</translation>
    </message>
    <message>
        <source>Scene, every parameter, the integrator and the exact current state</source>
        <translation>La scène, tous les paramètres, l’intégrateur et l’état actuel exact</translation>
    </message>
    <message>
        <source>Save scene &amp;as...</source>
        <translation>Enregistrer la scène &amp;sous...</translation>
    </message>
    <message>
        <source>Export &amp;Data (CSV, Excel)...</source>
        <translation>Exporter les &amp;données (CSV, Excel)...</translation>
    </message>
    <message>
        <source>The time series of this run, with the same columns as elastic-lab-cli run --csv</source>
        <translation>La série temporelle de cette simulation, avec les mêmes colonnes que elastic-lab-cli run --csv</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG, PDF)...</source>
        <translation>Exporter les &amp;graphiques (PNG, SVG, PDF)...</translation>
    </message>
    <message>
        <source>Save &amp;viewport screenshot...</source>
        <translation>Enregistrer une capture de la &amp;vue...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Quitter</translation>
    </message>
    <message>
        <source>&amp;Run / Pause</source>
        <translation>&amp;Lancer / Pause</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Pas</translation>
    </message>
    <message>
        <source>R&amp;eset</source>
        <translation>&amp;Réinitialiser</translation>
    </message>
    <message>
        <source>Reset &amp;view</source>
        <translation>Réinitialiser la &amp;vue</translation>
    </message>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>Mode &amp;présentation</translation>
    </message>
    <message>
        <source>Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector</source>
        <translation>Tout %1 fois plus grand, avec de grands boutons Lancer, Pas, Retour et Réinitialiser : pour un vidéoprojecteur</translation>
    </message>
    <message>
        <source>&amp;Larger text</source>
        <translation>Texte plus &amp;grand</translation>
    </message>
    <message>
        <source>S&amp;maller text</source>
        <translation>Texte plus &amp;petit</translation>
    </message>
    <message>
        <source>Structural springs</source>
        <translation>Ressorts structurels</translation>
    </message>
    <message>
        <source>Radius springs</source>
        <translation>Ressorts radiaux</translation>
    </message>
    <message>
        <source>Shear springs</source>
        <translation>Ressorts de cisaillement</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Faces</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Particules</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normales</translation>
    </message>
    <message>
        <source>Force vectors</source>
        <translation>Vecteurs de force</translation>
    </message>
    <message>
        <source>Colour springs by strain</source>
        <translation>Colorer les ressorts selon la déformation</translation>
    </message>
    <message>
        <source>Collision box</source>
        <translation>Boîte de collision</translation>
    </message>
    <message>
        <source>&amp;Side by side...</source>
        <translation>&amp;Côte à côte...</translation>
    </message>
    <message>
        <source>Single &amp;view</source>
        <translation>&amp;Vue unique</translation>
    </message>
    <message>
        <source>Elastic Lab &amp;help</source>
        <translation>&amp;Aide d’Elastic Lab</translation>
    </message>
    <message>
        <source>Guided experiments: a scene set up in one click, what to change, what to look at, the measured answer</source>
        <translation>Expériences guidées : une scène préparée en un clic, ce qu’il faut changer, ce qu’il faut observer, la réponse mesurée</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>À &amp;propos</translation>
    </message>
    <message>
        <source>About Elastic Lab</source>
        <translation>À propos d’Elastic Lab</translation>
    </message>
    <message>
        <source>Elastic Lab: the dynamics of two-layer elastic bodies, for teaching.</source>
        <translation>Elastic Lab : la dynamique des corps élastiques à deux couches, pour l’enseignement.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Fichier</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Fichiers &amp;récents</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulation</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Affichage</translation>
    </message>
    <message>
        <source>&amp;High contrast</source>
        <translation>&amp;Contraste élevé</translation>
    </message>
    <message>
        <source>White text on black, yellow highlight and focus: for low vision and projectors</source>
        <translation>Texte blanc sur noir, surbrillance et focus jaunes : pour la basse vision et les vidéoprojecteurs</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Comparer</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Préréglages</translation>
    </message>
    <message>
        <source>S&amp;tudies</source>
        <translation>É&amp;tudes</translation>
    </message>
    <message>
        <source>&amp;Work-precision study...</source>
        <translation>Étude &amp;travail-précision...</translation>
    </message>
    <message>
        <source>&amp;Refinement study...</source>
        <translation>Étude de &amp;raffinement...</translation>
    </message>
    <message>
        <source>&amp;Stability scan...</source>
        <translation>Balayage de &amp;stabilité...</translation>
    </message>
    <message>
        <source>&amp;Long-time energy...</source>
        <translation>Énergie sur la &amp;durée...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>&amp;Aide</translation>
    </message>
    <message>
        <source>DT set to %1 s</source>
        <translation>DT réglé à %1 s</translation>
    </message>
    <message>
        <source>Use implicit-euler</source>
        <translation>Utiliser implicit-euler</translation>
    </message>
    <message>
        <source>Linearised backward Euler: stable at any DT (and damps more)</source>
        <translation>Euler implicite linéarisé : stable pour tout DT (et amortit davantage)</translation>
    </message>
    <message>
        <source>Keep DT</source>
        <translation>Garder DT</translation>
    </message>
    <message>
        <source>Run with this DT anyway (to watch the method fail, for example)</source>
        <translation>Simuler quand même avec ce DT (pour voir la méthode échouer, par exemple)</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3, which this display does not offer.
Plots, parameters and exports still work.</source>
        <translation>La vue 3D demande OpenGL 3.3, que cet affichage n’offre pas.
Les graphiques, les paramètres et les exports fonctionnent toujours.</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Ouvrir une scène</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>Impossible d’ouvrir %1 : %2</translation>
    </message>
    <message>
        <source>Cannot build that body: %1</source>
        <translation>Impossible de construire ce corps : %1</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Langue</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Langue du système</translation>
    </message>
    <message>
        <source>Applies at the next start (now: %1)</source>
        <translation>S’applique au prochain démarrage (actuellement : %1)</translation>
    </message>
    <message>
        <source>The language changes when Elastic Lab starts again.</source>
        <translation>La langue change au prochain démarrage d’Elastic Lab.</translation>
    </message>
    <message>
        <source>Language: %1 at the next start</source>
        <translation>Langue : %1 au prochain démarrage</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Langue</translation>
    </message>
    <message>
        <source>Class controls</source>
        <translation>Commandes de classe</translation>
    </message>
    <message>
        <source>Presentation mode: text %1x (Ctrl+= larger, Ctrl+- smaller, F5 off)</source>
        <translation>Mode présentation : texte ×%1 (Ctrl+= plus grand, Ctrl+- plus petit, F5 pour quitter)</translation>
    </message>
    <message>
        <source>Normal text size</source>
        <translation>Taille de texte normale</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Modifications non enregistrées</translation>
    </message>
    <message>
        <source>The parameters or the integrator of %1 have changed since it was saved.</source>
        <translation>Les paramètres ou l’intégrateur de %1 ont changé depuis l’enregistrement.</translation>
    </message>
    <message>
        <source>Save stores the changes and the current state in the file.</source>
        <translation>Enregistrer écrit les modifications et l’état actuel dans le fichier.</translation>
    </message>
    <message>
        <source> Press Run (Space).</source>
        <translation> Appuyez sur Lancer (Espace).</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pause</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Lancer</translation>
    </message>
    <message>
        <source>&lt;b&gt;This body is likely unstable at the current DT.&lt;/b&gt; %1. The run is paused.</source>
        <translation>&lt;b&gt;Ce corps est probablement instable au DT actuel.&lt;/b&gt; %1. La simulation est en pause.</translation>
    </message>
    <message>
        <source>Use DT = %1 s</source>
        <translation>Utiliser DT = %1 s</translation>
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
        <translation>(aucun)</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>&amp;Effacer</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json);;All files (*)</source>
        <translation>Scènes Elastic Lab (*.json);;Tous les fichiers (*)</translation>
    </message>
    <message>
        <source>Could not open %1: not a regular file</source>
        <translation>Impossible d’ouvrir %1 : ce n’est pas un fichier ordinaire</translation>
    </message>
    <message>
        <source>Could not open %1: no such file</source>
        <translation>Impossible d’ouvrir %1 : fichier inexistant</translation>
    </message>
    <message>
        <source>Could not open %1: %2 bytes is too large for a scene file</source>
        <translation>Impossible d’ouvrir %1 : %2 octets, c’est trop pour un fichier de scène</translation>
    </message>
    <message>
        <source>%1 is not a scene this program can open:
%2</source>
        <translation>%1 n’est pas une scène que ce programme peut ouvrir :
%2</translation>
    </message>
    <message>
        <source>Opened %1: the saved state at t = %2 s, paused. Press Run (Space).</source>
        <translation>%1 ouvert : l’état enregistré à t = %2 s, en pause. Appuyez sur Lancer (Espace).</translation>
    </message>
    <message>
        <source>Opened %1 (no saved state: starts at t = 0). Press Run (Space).</source>
        <translation>%1 ouvert (pas d’état enregistré : départ à t = 0). Appuyez sur Lancer (Espace).</translation>
    </message>
    <message>
        <source>%1 no longer exists; it has been removed from the recent files.</source>
        <translation>%1 n’existe plus ; il a été retiré des fichiers récents.</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Fichiers récents</translation>
    </message>
    <message>
        <source>Save scene as</source>
        <translation>Enregistrer la scène sous</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json)</source>
        <translation>Scènes Elastic Lab (*.json)</translation>
    </message>
    <message>
        <source>Could not save %1: no scene is running yet</source>
        <translation>Impossible d’enregistrer %1 : aucune scène ne tourne encore</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Enregistrer la scène</translation>
    </message>
    <message>
        <source>Saved the first view (%1) at t = %2 s to %3; %4 not in the file.</source>
        <translation>Première vue (%1) à t = %2 s enregistrée dans %3 ; %4 pas dans le fichier.</translation>
    </message>
    <message>
        <source>the second view is</source>
        <translation>la deuxième vue n’est</translation>
    </message>
    <message>
        <source>the other views are</source>
        <translation>les autres vues ne sont</translation>
    </message>
    <message>
        <source>Saved %1 at t = %2 s (%3).</source>
        <translation>%1 enregistré à t = %2 s (%3).</translation>
    </message>
    <message>
        <source>CSV, comma and decimal point (*.csv)</source>
        <translation>CSV, virgule et point décimal (*.csv)</translation>
    </message>
    <message>
        <source>CSV for spreadsheets, semicolon and decimal comma (*.csv)</source>
        <translation>CSV pour tableurs, point-virgule et virgule décimale (*.csv)</translation>
    </message>
    <message>
        <source>Excel workbook with charts (*.xlsx)</source>
        <translation>Classeur Excel avec graphiques (*.xlsx)</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Exporter les données</translation>
    </message>
    <message>
        <source>Wrote %1 rows to %2</source>
        <translation>%1 lignes écrites dans %2</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>Exporter les graphiques</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>Image PNG (*.png);;Dessin SVG (*.svg);;Document PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 écrit</translation>
    </message>
    <message>
        <source>Save viewport screenshot</source>
        <translation>Enregistrer une capture de la vue</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Image PNG (*.png)</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Enregistrer la capture</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Pas en a&amp;rrière</translation>
    </message>
    <message>
        <source>Timeline s&amp;tart</source>
        <translation>&amp;Début de la chronologie</translation>
    </message>
    <message>
        <source>Timeline &amp;newest</source>
        <translation>Instant le plus &amp;récent</translation>
    </message>
    <message>
        <source>&amp;Clear abandoned future</source>
        <translation>Effacer le &amp;futur abandonné</translation>
    </message>
    <message>
        <source>Velocity vectors</source>
        <translation>Vecteurs vitesse</translation>
    </message>
    <message>
        <source>Ruler (drag to measure)</source>
        <translation>Règle (faire glisser pour mesurer)</translation>
    </message>
    <message>
        <source>Lesson &amp;texts (Experiments)...</source>
        <translation>&amp;Textes des leçons (Expériences)...</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Leçons</translation>
    </message>
    <message>
        <source>%1: set up. Lessons &gt; Lesson texts says what to change and what to look at. Press Run (Space).</source>
        <translation>%1 : préparé. Leçons &gt; Textes des leçons dit ce qu’il faut changer et observer. Appuyez sur Lancer (Espace).</translation>
    </message>
    <message>
        <source>Plotting the %1 against time (the Measured dock).</source>
        <translation>Tracé en fonction du temps : %1 (le dock Mesuré).</translation>
    </message>
    <message>
        <source>Particle %1</source>
        <translation>Particule %1</translation>
    </message>
    <message>
        <source>Plot its height</source>
        <translation>Tracer sa hauteur</translation>
    </message>
    <message>
        <source>Plot its speed</source>
        <translation>Tracer sa vitesse</translation>
    </message>
    <message>
        <source>Plot the inner layer&apos;s centre height</source>
        <translation>Tracer la hauteur du centre de la couche intérieure</translation>
    </message>
    <message>
        <source>Plot the outer layer&apos;s centre height</source>
        <translation>Tracer la hauteur du centre de la couche extérieure</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Corps</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass height</source>
        <translation>Tracer la hauteur du centre de masse</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass speed</source>
        <translation>Tracer la vitesse du centre de masse</translation>
    </message>
    <message>
        <source>Plot the layers&apos; separation</source>
        <translation>Tracer l’écart entre les couches</translation>
    </message>
    <message>
        <source>Several &amp;bodies</source>
        <translation>Plusieurs &amp;corps</translation>
    </message>
    <message>
        <source>%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body selector. Press Run (Space).</source>
        <translation>%1 : plusieurs corps. Le panneau Corps montre la quantité de mouvement et min_gap ; Paramètres a un sélecteur de corps. Appuyez sur Lancer (Espace).</translation>
    </message>
    <message>
        <source>Long-time energy</source>
        <translation>Énergie à long terme</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>Côte à côte</translation>
    </message>
</context>
<context>
    <name>elui::MeasurePlotDock</name>
    <message>
        <source>Measured</source>
        <translation>Mesuré</translation>
    </message>
    <message>
        <source>Right-click a particle or the body in the view to plot it here.</source>
        <translation>Clic droit sur une particule ou sur le corps dans la vue pour le tracer ici.</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Tout retirer</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>length [m]</source>
        <translation>longueur [m]</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>vitesse [m/s]</translation>
    </message>
</context>
<context>
    <name>elui::Pacer</name>
    <message>
        <source>Real time</source>
        <translation>Temps réel</translation>
    </message>
    <message>
        <source>1/4 speed</source>
        <translation>Vitesse 1/4</translation>
    </message>
    <message>
        <source>1/10 speed</source>
        <translation>Vitesse 1/10</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>Aussi vite que possible</translation>
    </message>
</context>
<context>
    <name>elui::ParameterDock</name>
    <message>
        <source>Parameters</source>
        <translation>Paramètres</translation>
    </message>
    <message>
        <source>Every parameter of the scene with its unit; a change applies at once</source>
        <translation>Tous les paramètres de la scène avec leur unité ; une modification s’applique aussitôt</translation>
    </message>
    <message>
        <source>Reset all to the scene&apos;s defaults</source>
        <translation>Tout aux valeurs par défaut</translation>
    </message>
    <message>
        <source>Every parameter here (and DT) back to the scene&apos;s default; the body&apos;s shape stays (Scene dock).</source>
        <translation>Chaque paramètre ici (et DT) revient à la valeur par défaut de la scène ; la forme du corps reste (dock Scène).</translation>
    </message>
    <message>
        <source>The body whose parameters are shown and edited; world parameters (gravity, box, contact, dt) are every body&apos;s.</source>
        <translation>Le corps dont les paramètres sont affichés et modifiés ; les paramètres du monde (gravité, boîte, contact, dt) sont ceux de chaque corps.</translation>
    </message>
    <message>
        <source>body%1 (%2)</source>
        <translation>body%1 (%2)</translation>
    </message>
    <message>
        <source>every body</source>
        <translation>tous les corps</translation>
    </message>
</context>
<context>
    <name>elui::ParameterForm</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;default: %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;par défaut : %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;allowed: %4&lt;br&gt;default: %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;autorisé : %4&lt;br&gt;par défaut : %5</translation>
    </message>
    <message>
        <source>Set DT in the Run dock.</source>
        <translation>Réglez DT dans le dock Simulation.</translation>
    </message>
    <message>
        <source>key: %1</source>
        <translation>clé : %1</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number; allowed %3</source>
        <translation>%1 : « %2 » n’est pas un nombre ; autorisé %3</translation>
    </message>
    <message>
        <source>%1 = %2 is not allowed; allowed %3%4</source>
        <translation>%1 = %2 n’est pas autorisé ; autorisé %3%4</translation>
    </message>
    <message>
        <source>, whole numbers</source>
        <translation>, nombres entiers</translation>
    </message>
    <message>
        <source>Back to the default: %1</source>
        <translation>Revenir à la valeur par défaut : %1</translation>
    </message>
    <message>
        <source>Back to the default: %1 %2</source>
        <translation>Revenir à la valeur par défaut : %1 %2</translation>
    </message>
    <message>
        <source>%1 from %2 to %3 %4%5 (the field takes any value in %6)</source>
        <translation>%1 de %2 à %3 %4%5 (le champ accepte toute valeur dans %6)</translation>
    </message>
    <message>
        <source>, logarithmic</source>
        <translation>, logarithmique</translation>
    </message>
</context>
<context>
    <name>elui::PlotDock</name>
    <message>
        <source>Plots</source>
        <translation>Graphiques</translation>
    </message>
    <message>
        <source>Last 5 s</source>
        <translation>5 dernières s</translation>
    </message>
    <message>
        <source>Last 10 s</source>
        <translation>10 dernières s</translation>
    </message>
    <message>
        <source>Last 30 s</source>
        <translation>30 dernières s</translation>
    </message>
    <message>
        <source>Full history</source>
        <translation>Historique complet</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Échelle auto</translation>
    </message>
    <message>
        <source>Fit the axes to the data; off while you zoom (wheel) and pan (drag)</source>
        <translation>Ajuster les axes aux données ; désactivé pendant que vous zoomez (molette) et déplacez (glisser)</translation>
    </message>
    <message>
        <source>Show per-step error band</source>
        <translation>Afficher la bande d’erreur par pas</translation>
    </message>
    <message>
        <source>A band around volume, pressure and total energy: the integrator&apos;s local error estimate of each step carried to them (|O(y + e) - O(y)|): the error one step adds, not the error of the run so far, which can be far larger. rk45, CVODE and step doubling have an estimate; other methods show no band.</source>
        <translation>Une bande autour du volume, de la pression et de l’énergie totale : l’estimation d’erreur locale de l’intégrateur à chaque pas, reportée sur elles (|O(y + e) - O(y)|) : l’erreur qu’ajoute un pas, pas l’erreur accumulée de la simulation, qui peut être bien plus grande. rk45, CVODE et le doublement de pas ont une estimation ; les autres méthodes n’affichent pas de bande.</translation>
    </message>
    <message>
        <source>Time window of the plots</source>
        <translation>Fenêtre de temps des graphiques</translation>
    </message>
    <message>
        <source>How much of the run the plots show: the last seconds, or all of it</source>
        <translation>Quelle part de la simulation les graphiques montrent : les dernières secondes, ou tout</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Afficher</translation>
    </message>
    <message>
        <source>Energy drift per view</source>
        <translation>Dérive d’énergie par vue</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|drift| [J]</source>
        <translation>|dérive| [J]</translation>
    </message>
    <message>
        <source>✕ a view failed</source>
        <translation>✕ une vue a échoué</translation>
    </message>
    <message>
        <source>%1 against simulated time; the numbers are in the Run dock&apos;s readout and in File &gt; Export Data</source>
        <translation>%1 en fonction du temps simulé ; les nombres sont dans l’affichage du dock Simulation et dans Fichier &gt; Exporter les données</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source> (abandoned)</source>
        <translation> (abandonné)</translation>
    </message>
    <message>
        <source> error band</source>
        <translation> bande d’erreur</translation>
    </message>
    <message>
        <source>No band: this integrator gives no error estimate. Use rk45, CVODE, or tick &quot;Estimate error (step doubling)&quot; in the Run dock.</source>
        <translation>Pas de bande : cet intégrateur ne donne pas d’estimation d’erreur. Utilisez rk45, CVODE, ou cochez « Estimer l’erreur (doublement de pas) » dans le dock Simulation.</translation>
    </message>
    <message>
        <source>The band is there but thinner than a line: each step&apos;s error estimate is below half a pixel at this zoom (an adaptive method keeps it under its tolerance). Loosen rtol/atol in the Run dock, or use a fixed-step method at a larger DT with step doubling, to see it.</source>
        <translation>La bande est là, mais plus fine qu’un trait : l’estimation d’erreur de chaque pas est sous le demi-pixel à ce zoom (une méthode adaptative la maintient sous sa tolérance). Relâchez rtol/atol dans le dock Simulation, ou utilisez une méthode à pas fixe à un DT plus grand avec doublement de pas, pour la voir.</translation>
    </message>
    <message>
        <source>Band: the error each step adds (a per-step estimate), not the error of the run so far.</source>
        <translation>Bande : l’erreur qu’ajoute chaque pas (une estimation par pas), pas l’erreur accumulée de la simulation.</translation>
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
        <translation>Volume, pression et énergie en fonction du temps simulé, un graphique sous l’autre</translation>
    </message>
    <message>
        <source>Reference curve (rk45)</source>
        <translation>Courbe de référence (rk45)</translation>
    </message>
    <message>
        <source>A converged solution (rk45 at tolerance 1e-10) from the run&apos;s start, computed beside the run on a thread of its own and drawn dashed: the distance between a curve and it is the error of the run so far (the global error), where the band is the error one step adds. It follows the run up to the first change of the physics (a parameter edit other than DT, or a drag).</source>
        <translation>Une solution convergée (rk45 à la tolérance 1e-10) depuis le début de la simulation, calculée à côté dans un fil à part et tracée en tirets : l’écart entre une courbe et elle est l’erreur accumulée de la simulation (l’erreur globale), alors que la bande est l’erreur qu’ajoute un pas. Elle suit la simulation jusqu’au premier changement de la physique (une modification de paramètre autre que DT, ou un glissement).</translation>
    </message>
    <message>
        <source>reference (rk45, 1e-10)</source>
        <translation>référence (rk45, 1e-10)</translation>
    </message>
    <message>
        <source>Reference: computing from the run&apos;s start…</source>
        <translation>Référence : calcul depuis le début de la simulation…</translation>
    </message>
    <message>
        <source>At t = %1 s the run&apos;s total energy is %2 J from the reference: the error of the run so far.</source>
        <translation>À t = %1 s, l’énergie totale de la simulation est à %2 J de la référence : l’erreur accumulée de la simulation.</translation>
    </message>
    <message>
        <source>The band there, one step&apos;s error: ±%1 J.</source>
        <translation>La bande à cet endroit, l’erreur d’un pas : ±%1 J.</translation>
    </message>
    <message>
        <source>The reference itself failed at t = %1 s (%2): the body fails at every step size.</source>
        <translation>La référence elle-même a échoué à t = %1 s (%2) : le corps échoue à tout pas de temps.</translation>
    </message>
    <message>
        <source>The run was changed at t = %1 s (a parameter edit or a drag): the reference stops there.</source>
        <translation>La simulation a été modifiée à t = %1 s (une modification de paramètre ou un glissement) : la référence s’arrête là.</translation>
    </message>
    <message>
        <source>The reference has reached t = %1 s (computing).</source>
        <translation>La référence a atteint t = %1 s (calcul en cours).</translation>
    </message>
</context>
<context>
    <name>elui::PvDock</name>
    <message>
        <source>P–V diagram</source>
        <translation>Diagramme P–V</translation>
    </message>
    <message>
        <source>Whole curve (0.5 to 1.5 × rest volume)</source>
        <translation>Courbe entière (0,5 à 1,5 × volume au repos)</translation>
    </message>
    <message>
        <source>Off: the axes fit the trail, to see it move. On: a wide stretch of the isotherm, to see where on it the layer sits.</source>
        <translation>Désactivé : les axes suivent la trace, pour la voir bouger. Activé : une large portion de l’isotherme, pour voir où la couche s’y trouve.</translation>
    </message>
    <message>
        <source>inner layer</source>
        <translation>couche intérieure</translation>
    </message>
    <message>
        <source>outer layer</source>
        <translation>couche extérieure</translation>
    </message>
    <message>
        <source>Pressure against volume, %1</source>
        <translation>Pression en fonction du volume, %1</translation>
    </message>
    <message>
        <source>The trail of the layer&apos;s gas in the P-V plane and its isotherm</source>
        <translation>La trace du gaz de la couche dans le plan P-V et son isotherme</translation>
    </message>
    <message>
        <source>P–V, %1</source>
        <translation>P–V, %1</translation>
    </message>
    <message>
        <source>trail</source>
        <translation>trace</translation>
    </message>
    <message>
        <source>now</source>
        <translation>maintenant</translation>
    </message>
    <message>
        <source>area V [m²]</source>
        <translation>aire V [m²]</translation>
    </message>
    <message>
        <source>volume V [m³]</source>
        <translation>volume V [m³]</translation>
    </message>
    <message>
        <source>pressure P [N/m]</source>
        <translation>pression P [N/m]</translation>
    </message>
    <message>
        <source>pressure P [Pa]</source>
        <translation>pression P [Pa]</translation>
    </message>
    <message>
        <source>%1 has no gas: no P–V diagram.</source>
        <translation>%1 n’a pas de gaz : pas de diagramme P–V.</translation>
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
        <translation>Étude de raffinement</translation>
    </message>
    <message>
        <source>Values of the scene&apos;s resolution, separated by spaces; the finest is the reference</source>
        <translation>Valeurs de la résolution de la scène, séparées par des espaces ; la plus fine sert de référence</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automatique</translation>
    </message>
    <message>
        <source>Fixed step DT [s] for every level; it must divide 0.01 s and be stable at the finest level. Empty: a quarter of the smaller of the scene&apos;s DT and the finest level&apos;s stable step</source>
        <translation>Pas fixe DT [s] pour chaque niveau ; il doit diviser 0.01 s et être stable au niveau le plus fin. Vide : un quart du plus petit entre le DT de la scène et le pas stable du niveau le plus fin</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Temps simulé de chaque simulation [s]</translation>
    </message>
    <message>
        <source>Levels</source>
        <translation>Niveaux</translation>
    </message>
    <message>
        <source>Levels (%1)</source>
        <translation>Niveaux (%1)</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Durée T [s]</translation>
    </message>
    <message>
        <source>run time [s]</source>
        <translation>temps de calcul [s]</translation>
    </message>
    <message>
        <source>max relative volume error</source>
        <translation>erreur relative max. de volume</translation>
    </message>
    <message>
        <source>max centre-of-mass error [m]</source>
        <translation>erreur max. du centre de masse [m]</translation>
    </message>
    <message>
        <source>Choose exactly one integrator</source>
        <translation>Choisissez exactement un intégrateur</translation>
    </message>
    <message>
        <source>DT must be a number in seconds, or empty for the automatic step</source>
        <translation>DT doit être un nombre en secondes, ou vide pour le pas automatique</translation>
    </message>
    <message>
        <source>Levels are whole numbers separated by spaces, got &apos;%1&apos;</source>
        <translation>Les niveaux sont des entiers séparés par des espaces ; reçu « %1 »</translation>
    </message>
    <message>
        <source>level (%1)</source>
        <translation>niveau (%1)</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>particules</translation>
    </message>
    <message>
        <source>springs</source>
        <translation>ressorts</translation>
    </message>
    <message>
        <source>h [m]</source>
        <translation>h [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <source>volume error</source>
        <translation>erreur de volume</translation>
    </message>
    <message>
        <source>centre-of-mass error [m]</source>
        <translation>erreur du centre de masse [m]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>état</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>référence</translation>
    </message>
    <message>
        <source>mesh (%1)</source>
        <translation>maillage (%1)</translation>
    </message>
    <message>
        <source>step (%1=%2, coarser DT)</source>
        <translation>pas (%1=%2, DT plus grossier)</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Échec : %1</translation>
    </message>
    <message>
        <source>Time error of that step (measured at %1=%2): volume %3, centre of mass %4 m. </source>
        <translation>Erreur temporelle de ce pas (mesurée à %1=%2) : volume %3, centre de masse %4 m. </translation>
    </message>
    <message>
        <source>Spatial order (%1): %2. </source>
        <translation>Ordre spatial (%1) : %2. </translation>
    </message>
    <message>
        <source>Spatial order (%1): not resolved. </source>
        <translation>Ordre spatial (%1) : non résolu. </translation>
    </message>
</context>
<context>
    <name>elui::RunDock</name>
    <message>
        <source>Run</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>side by side (see each view)</source>
        <translation>côte à côte (voir chaque vue)</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Intégrateur</translation>
    </message>
    <message>
        <source>The method that advances the body in time; each one&apos;s order and idea are in its item&apos;s tooltip and in Help</source>
        <translation>La méthode qui fait avancer le corps dans le temps ; l’ordre et l’idée de chacune sont dans l’infobulle de son entrée et dans l’Aide</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>rk45, cvode-bdf and cvode-adams choose their steps so that each step&apos;s error estimate stays below atol + rtol |y| (as elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] (m and m/s). Smaller: smaller steps, more force evaluations, a thinner error band.</source>
        <translation>rk45, cvode-bdf et cvode-adams choisissent leurs pas pour que l’estimation d’erreur de chaque pas reste sous atol + rtol |y| (comme elastic-lab-cli --atol, --rtol). rtol dans (0, 1], atol dans [0, 1] (m et m/s). Plus petit : des pas plus petits, plus d’évaluations de force, une bande d’erreur plus fine.</translation>
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
        <translation>Tolérance</translation>
    </message>
    <message>
        <source>How fast simulated time runs against the wall clock</source>
        <translation>À quelle vitesse le temps simulé s’écoule par rapport à l’horloge</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Vitesse</translation>
    </message>
    <message>
        <source>Run or pause the simulation (Space)</source>
        <translation>Lancer ou mettre en pause la simulation (Espace)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Pas</translation>
    </message>
    <message>
        <source>One step DT forward (S)</source>
        <translation>Un pas DT en avant (S)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Réinitialiser</translation>
    </message>
    <message>
        <source>Back to the start state with the same parameters (Ctrl+R)</source>
        <translation>Retour à l’état initial avec les mêmes paramètres (Ctrl+R)</translation>
    </message>
    <message>
        <source>Estimate error (step doubling)</source>
        <translation>Estimer l’erreur (doublement de pas)</translation>
    </message>
    <message>
        <source>Fixed-step integrators: estimate the local error by taking each step also as two half steps. Costs about twice the work. rk45 always reports its own estimate.</source>
        <translation>Intégrateurs à pas fixe : estimer l’erreur locale en faisant chaque pas aussi en deux demi-pas. Coûte environ deux fois plus de travail. rk45 fournit toujours sa propre estimation.</translation>
    </message>
    <message>
        <source>Readout</source>
        <translation>Affichage</translation>
    </message>
    <message>
        <source>Time, steps, energies and the energy balance of the run</source>
        <translation>Temps, pas, énergies et bilan d’énergie de la simulation</translation>
    </message>
    <message>
        <source>rtol: &apos;%1&apos; is not a number in (0, 1]</source>
        <translation>rtol : « %1 » n’est pas un nombre dans (0, 1]</translation>
    </message>
    <message>
        <source>atol: &apos;%1&apos; is not a number in [0, 1]</source>
        <translation>atol : « %1 » n’est pas un nombre dans [0, 1]</translation>
    </message>
    <message>
        <source>Each view</source>
        <translation>Chaque vue</translation>
    </message>
    <message>
        <source>view</source>
        <translation>vue</translation>
    </message>
    <message>
        <source>time</source>
        <translation>temps</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>dérive d’énergie</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>échec</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pause</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>temps simulé</translation>
    </message>
    <message>
        <source>wall time</source>
        <translation>temps de calcul</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>pas/s</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>en pause</translation>
    </message>
    <message>
        <source>step taken</source>
        <translation>pas effectué</translation>
    </message>
    <message>
        <source>error estimate</source>
        <translation>estimation d’erreur</translation>
    </message>
    <message>
        <source>off</source>
        <translation>désactivé</translation>
    </message>
    <message>
        <source>contact energy</source>
        <translation>énergie de contact</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>retiré par le contact</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>évaluations de force</translation>
    </message>
    <message>
        <source>CVODE steps / RHS</source>
        <translation>pas CVODE / RHS</translation>
    </message>
    <message>
        <source>Jv products / linear it.</source>
        <translation>produits Jv / it. linéaires</translation>
    </message>
    <message>
        <source>error-test / conv. failures</source>
        <translation>échecs test d’erreur / conv.</translation>
    </message>
    <message>
        <source>order, re-initialisations</source>
        <translation>ordre, réinitialisations</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b35900&apos;&gt;Cannot keep up with real time: showing as fast as it runs.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b35900&apos;&gt;Impossible de suivre le temps réel : affichage aussi rapide que le calcul.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>order %1: %2</source>
        <translation>ordre %1 : %2</translation>
    </message>
    <message>
        <source>%1; allowed %2 s</source>
        <translation>%1 ; autorisé %2 s</translation>
    </message>
    <message>
        <source>Relative tolerance rtol</source>
        <translation>Tolérance relative rtol</translation>
    </message>
    <message>
        <source>Absolute tolerance atol</source>
        <translation>Tolérance absolue atol</translation>
    </message>
    <message>
        <source>Run</source>
        <comment>button: start the simulation</comment>
        <translation>Lancer</translation>
    </message>
    <message>
        <source>distance&lt;br&gt;to view %1</source>
        <translation>distance&lt;br&gt;à la vue %1</translation>
    </message>
    <message>
        <source>double</source>
        <translation>double (64 bits)</translation>
    </message>
    <message>
        <source>float</source>
        <translation>simple (32 bits)</translation>
    </message>
    <message>
        <source>double: state and forces in 64-bit numbers. float: in 32-bit numbers, as fast engines and games compute (euler, midpoint, rk4, symplectic-euler, verlet; one view; no walls or mouse: the run stops at a wall, a held particle steps in double). The readout shows how far the float run is from double.</source>
        <translation>double : état et forces en nombres de 64 bits. simple : en nombres de 32 bits, comme calculent les moteurs rapides et les jeux (euler, midpoint, rk4, symplectic-euler, verlet ; une seule vue ; ni murs ni souris : le calcul s&apos;arrête à un mur, une particule tenue avance en double). L&apos;affichage montre l&apos;écart entre le calcul en simple et le calcul en double.</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Précision</translation>
    </message>
    <message>
        <source>precision</source>
        <translation>précision</translation>
    </message>
    <message>
        <source>double while held</source>
        <translation>double tant que tenu</translation>
    </message>
    <message>
        <source>float − double</source>
        <translation>simple − double</translation>
    </message>
    <message>
        <source>round-off (est.)</source>
        <translation>arrondi (estimé)</translation>
    </message>
</context>
<context>
    <name>elui::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Scène</translation>
    </message>
    <message>
        <source>The body to build: a spring, a two-layer ring or a two-layer sphere</source>
        <translation>Le corps à construire : un ressort, un anneau à deux couches ou une sphère à deux couches</translation>
    </message>
    <message>
        <source>Rebuild body</source>
        <translation>Reconstruire le corps</translation>
    </message>
    <message>
        <source>Build the chosen scene with this shape and start again from rest</source>
        <translation>Construire la scène choisie avec cette forme et repartir du repos</translation>
    </message>
    <message>
        <source>Body values</source>
        <translation>Valeurs du corps</translation>
    </message>
    <message>
        <source>What the parameters mean for the body that runs: under scaling=physical the values hold at the scene&apos;s default resolution and a finer mesh keeps the body&apos;s totals; under scaling=thesis they are per particle and per spring</source>
        <translation>Ce que les paramètres signifient pour le corps simulé : avec scaling=physical, les valeurs valent pour la résolution par défaut de la scène et un maillage plus fin conserve les totaux du corps ; avec scaling=thesis, elles s’entendent par particule et par ressort</translation>
    </message>
    <message>
        <source>This body uses: %1</source>
        <translation>Ce corps utilise : %1</translation>
    </message>
    <message>
        <source>The body to build, its shape and what its parameters mean</source>
        <translation>Le corps à construire, sa forme et ce que signifient ses paramètres</translation>
    </message>
</context>
<context>
    <name>elui::StabilityDialog</name>
    <message>
        <source>Stability scan</source>
        <translation>Balayage de stabilité</translation>
    </message>
    <message>
        <source>Each trial runs this long; a run that does not blow up and whose energy stays bounded is stable</source>
        <translation>Chaque essai dure ce temps ; une simulation qui n’explose pas et dont l’énergie reste bornée est stable</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Durée T [s]</translation>
    </message>
    <message>
        <source>largest stable DT [s]</source>
        <translation>plus grand DT stable [s]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>intégrateur</translation>
    </message>
    <message>
        <source>linearising</source>
        <translation>linéarisation</translation>
    </message>
    <message>
        <source>stable DT [s]</source>
        <translation>DT stable [s]</translation>
    </message>
    <message>
        <source>unstable DT [s]</source>
        <translation>DT instable [s]</translation>
    </message>
    <message>
        <source>predicted DT [s]</source>
        <translation>DT prédit [s]</translation>
    </message>
    <message>
        <source>h·ω at stable</source>
        <translation>h·ω au stable</translation>
    </message>
    <message>
        <source>why it failed above</source>
        <translation>pourquoi il a échoué au-delà</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>mesuré</translation>
    </message>
    <message>
        <source>linearised prediction</source>
        <translation>prédiction linéarisée</translation>
    </message>
    <message>
        <source>Highest mode of the linearised body: ω = %1 rad/s (damping %2 1/s), %3 free coordinates. A method is stable at DT when no mode grows; measured by bisection over %4 s runs.</source>
        <translation>Mode le plus haut du corps linéarisé : ω = %1 rad/s (amortissement %2 1/s), %3 coordonnées libres. Une méthode est stable à DT quand aucun mode ne croît ; mesuré par dichotomie sur des simulations de %4 s.</translation>
    </message>
    <message>
        <source>Duration must be a positive number of seconds</source>
        <translation>La durée doit être un nombre positif de secondes</translation>
    </message>
</context>
<context>
    <name>elui::StabilityMapDock</name>
    <message>
        <source>Stability map</source>
        <translation>Carte de stabilité</translation>
    </message>
    <message>
        <source>The integrator&apos;s stability region and the body&apos;s eigenvalues times DT; the margin is written below the map</source>
        <translation>La région de stabilité de l’intégrateur et les valeurs propres du corps multipliées par DT ; la marge est écrite sous la carte</translation>
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
        <translation>région de stabilité</translation>
    </message>
    <message>
        <source>DT·λ, every mode</source>
        <translation>DT·λ, tous les modes</translation>
    </message>
    <message>
        <source>leaves first</source>
        <translation>sort en premier</translation>
    </message>
    <message>
        <source>measured limit</source>
        <translation>limite mesurée</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>Essayer</translation>
    </message>
    <message>
        <source>Waiting for a body…</source>
        <translation>En attente d’un corps…</translation>
    </message>
    <message>
        <source>Linearising the body…</source>
        <translation>Linéarisation du corps…</translation>
    </message>
    <message>
        <source>edge (radius 1)</source>
        <translation>bord (rayon 1)</translation>
    </message>
    <message>
        <source>edge |R| = 1</source>
        <translation>bord |R| = 1</translation>
    </message>
    <message>
        <source>edge of view %1 (%2)</source>
        <translation>bord de la vue %1 (%2)</translation>
    </message>
    <message>
        <source>Re(hλ), h = DT = %1 s</source>
        <translation>Re(hλ), h = DT = %1 s</translation>
    </message>
    <message>
        <source>View %1, %2 (filled): %3</source>
        <translation>Vue %1, %2 (plein) : %3</translation>
    </message>
    <message>
        <source>View %1, %2 (dashed): %3</source>
        <translation>Vue %1, %2 (tirets) : %3</translation>
    </message>
    <message>
        <source>Eigenvalues: %1.
%2</source>
        <translation>Valeurs propres : %1.
%2</translation>
    </message>
    <message>
        <source>%1 has no fixed stability limit to measure</source>
        <translation>%1 n’a pas de limite de stabilité fixe à mesurer</translation>
    </message>
    <message>
        <source>Measured: no stable DT down to 1e-5 s.</source>
        <translation>Mesuré : aucun DT stable jusqu’à 1e-5 s.</translation>
    </message>
    <message>
        <source>Measured: stable up to the largest DT scanned, %1 s</source>
        <translation>Mesuré : stable jusqu’au plus grand DT balayé, %1 s</translation>
    </message>
    <message>
        <source>Measured: stable at DT = %1 s, blows up at %2 s</source>
        <translation>Mesuré : stable à DT = %1 s, explose à %2 s</translation>
    </message>
    <message>
        <source> (%1 runs of %2 s; predicted %3 s).</source>
        <translation> (%1 simulations de %2 s ; prédit %3 s).</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>illimité</translation>
    </message>
    <message>
        <source> ✕ = the ringed mode at the measured DT.</source>
        <translation> ✕ = le mode entouré au DT mesuré.</translation>
    </message>
    <message>
        <source> ✕ = the fastest mode at the measured DT.</source>
        <translation> ✕ = le mode le plus rapide au DT mesuré.</translation>
    </message>
    <message>
        <source>Measuring the largest stable DT of %1…</source>
        <translation>Mesure du plus grand DT stable de %1…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Annulation…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Measurement cancelled.</source>
        <translation>Mesure annulée.</translation>
    </message>
    <message>
        <source>The body or the integrator changed during the measurement: press Try it again.</source>
        <translation>Le corps ou l’intégrateur a changé pendant la mesure : appuyez de nouveau sur Essayer.</translation>
    </message>
    <message>
        <source>Measure this integrator&apos;s largest stable DT on this body or world: the stability scan&apos;s bisection (%1 s runs; Studies → Stability scan does all integrators), marked on the picture</source>
        <translation>Mesurer le plus grand DT stable de cet intégrateur sur ce corps ou ce monde : la bissection du balayage de stabilité (essais de %1 s ; Études → Balayage de stabilité les fait tous), marqué sur l&apos;image</translation>
    </message>
    <message>
        <source>Linearising the world (%1 bodies)…</source>
        <translation>Linéarisation du monde (%1 corps)…</translation>
    </message>
    <message>
        <source>The whole world (%1 bodies) linearised as one system: every body&apos;s modes, and the contact between bodies where two are within the contact skin. </source>
        <translation>Le monde entier (%1 corps) linéarisé comme un seul système : les modes de chaque corps, et le contact entre corps là où deux sont dans la peau de contact. </translation>
    </message>
    <message>
        <source>the fastest mode</source>
        <translation>le mode le plus rapide</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1, a pure decay)</source>
        <translation>le mode le plus rapide (hλ = %1, décroissance pure)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1, a pure decay)</source>
        <translation>le mode (hλ = %1, décroissance pure)</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1 ± %2i)</source>
        <translation>le mode le plus rapide (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1 ± %2i)</source>
        <translation>le mode (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>per mode, modal damping</source>
        <translation>mode par mode, amortissement modal</translation>
    </message>
    <message>
        <source>xpbd is stable at every DT: no margin to give.</source>
        <translation>xpbd est stable quel que soit DT : il n’y a pas de marge à indiquer.</translation>
    </message>
    <message>
        <source>%1 chooses its own internal steps: no DT limit from stability.</source>
        <translation>%1 choisit lui-même ses pas internes : la stabilité ne limite pas DT.</translation>
    </message>
    <message>
        <source>No DT limit: every mode of this body stays in the region for any DT.</source>
        <translation>Pas de limite sur DT : tous les modes de ce corps restent dans la région, quel que soit DT.</translation>
    </message>
    <message>
        <source>No DT is stable: a mode pair grows for every DT (%1).</source>
        <translation>Aucun DT n’est stable : une paire de modes croît pour tout DT (%1).</translation>
    </message>
    <message>
        <source>No DT is stable: %1 sits where the region only touches the imaginary axis at 0; it grows for every DT (slowly when DT is small).</source>
        <translation>Aucun DT n’est stable : %1 se trouve là où la région ne touche l’axe imaginaire qu’en 0 ; il croît pour tout DT (lentement si DT est petit).</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before a mode pair goes unstable (%3); the picture is exact for underdamped modes only.</source>
        <translation>DT peut être multiplié par %1 (jusqu’à %2 s) avant qu’une paire de modes ne devienne instable (%3) ; l’image n’est exacte que pour les modes sous-amortis.</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before %3 leaves the region.</source>
        <translation>DT peut être multiplié par %1 (jusqu’à %2 s) avant que %3 ne sorte de la région.</translation>
    </message>
    <message>
        <source>DT is already outside the stable range (%1): shrink DT by %2× (to %3 s).</source>
        <translation>DT est déjà hors du domaine stable (%1) : réduisez DT d’un facteur %2 (à %3 s).</translation>
    </message>
    <message>
        <source>DT is already outside: %1 is out of the region; shrink DT by %2× (to %3 s) to bring it back.</source>
        <translation>DT est déjà trop grand : %1 est hors de la région ; réduisez DT d’un facteur %2 (à %3 s) pour l’y ramener.</translation>
    </message>
    <message>
        <source>exact spectrum: all %1 eigenvalues of the linearised first-order system (dense eigen-solve)</source>
        <translation>spectre exact : les %1 valeurs propres du système linéarisé du premier ordre (résolution dense)</translation>
    </message>
    <message>
        <source>modal: all %1 modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; λ = −c/2 ± i√(ω² − c²/4)</source>
        <translation>modal : les %1 modes de M⁻¹K (problème aux valeurs propres symétrique), amortissement c = φᵀ(M⁻¹D)φ par mode ; λ = −c/2 ± i√(ω² − c²/4)</translation>
    </message>
    <message>
        <source>iterative: %1 Ritz values of the first-order system, Arnoldi (%2 steps) on the Jacobian products, %3 free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner ones are not</source>
        <translation>itératif : %1 valeurs de Ritz du système du premier ordre, Arnoldi (%2 itérations) sur les produits par la jacobienne, %3 coordonnées libres : les valeurs propres extrêmes (plus grand |λ|) sont précises, les intérieures ne le sont pas</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis up to ±%1i: undamped modes are stable up to hω = 2√2.</source>
        <translation>Région : |R(hλ)| ≤ 1 pour son polynôme de stabilité R (le polynôme de Taylor de e^z) ; elle touche l’axe imaginaire jusqu’à ±%1i : les modes non amortis sont stables jusqu’à hω = 2√2.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis only at 0: an undamped mode grows for every DT.</source>
        <translation>Région : |R(hλ)| ≤ 1 pour son polynôme de stabilité R (le polynôme de Taylor de e^z) ; elle ne touche l’axe imaginaire qu’en 0 : un mode non amorti croît pour tout DT.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for Dormand–Prince&apos;s 5th-order solution, R = Taylor to z⁵ + z⁶/600, taken at a fixed step. The adaptive run picks its own step from the error tolerance: it does not blow up, it takes smaller steps.</source>
        <translation>Région : |R(hλ)| ≤ 1 pour la solution d’ordre 5 de Dormand–Prince, R = Taylor jusqu’à z⁵ + z⁶/600, prise à pas fixe. La simulation adaptative choisit son pas d’après la tolérance d’erreur : elle n’explose pas, elle fait des pas plus petits.</translation>
    </message>
    <message>
        <source>Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| &lt; 1, the whole left half-plane (A-stable): no DT limit from stability.</source>
        <translation>Région : |1/(1 − hλ)| ≤ 1, tout l’extérieur du disque |1 − hλ| &lt; 1, donc tout le demi-plan gauche (A-stable) : la stabilité ne limite pas DT.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Région : pas de R scalaire ; tracée pour un mode d’oscillateur dont la paire de valeurs propres est hλ, hλ̄ (exacte quand les modes se découplent ; l’axe réel montre le mode à amortissement critique). Modes non amortis : hω ≤ 2. La marge vient de la matrice de pas, non de l’image.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, damping at the half-step velocity (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Région : pas de R scalaire ; tracée pour un mode d’oscillateur dont la paire de valeurs propres est hλ, hλ̄, l’amortissement étant pris à la vitesse du demi-pas (exacte quand les modes se découplent ; l’axe réel montre le mode à amortissement critique). Modes non amortis : hω ≤ 2. La marge vient de la matrice de pas, non de l’image.</translation>
    </message>
    <message>
        <source>Region: no scalar R; the step is a product of %1 Verlet substeps (some backwards), drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the half-kick velocity, as the integrator does), traced ray by ray from 0. Undamped modes: hω ≤ %2 (a step costs %3 force evaluations). The margin uses the step matrix, not the picture.</source>
        <translation>Région : pas de R scalaire ; le pas est un produit de %1 sous-pas de Verlet (certains à rebours), tracée pour un mode d’oscillateur dont la paire de valeurs propres est hλ, hλ̄ (amortissement pris à la vitesse de chaque demi-impulsion, comme le fait l’intégrateur), rayon par rayon depuis 0. Modes non amortis : hω ≤ %2 (un pas coûte %3 évaluations de force). La marge vient de la matrice de pas, non de l’image.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed region. BDF1–2 are A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the step or the order when a mode threatens: no DT limit, DT is only the output interval.</source>
        <translation>Pas de région : BDF adaptatif d’ordre variable (ordres 1–5), à contrôle d’erreur, sans région fixe. BDF1–2 sont A-stables, BDF3–5 A(α)-stables jusqu’à α ≈ 51° ; CVODE réduit le pas ou l’ordre dès qu’un mode menace : pas de limite sur DT, DT n’est que l’intervalle de sortie.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed region. Its regions are small (explicit-like); CVODE keeps the internal step inside them by its error test: no DT limit, stiff bodies only cost steps.</source>
        <translation>Pas de région : Adams adaptatif d’ordre variable (ordres 1–12), à contrôle d’erreur, sans région fixe. Ses régions sont petites (comme celles d’une méthode explicite) ; CVODE y maintient le pas interne par son test d’erreur : pas de limite sur DT, un corps raide ne coûte que des pas.</translation>
    </message>
    <message>
        <source>No region: XPBD projects the springs as compliant constraints (compliance 1/ks): unconditionally stable, no region in the hλ plane; large DT costs accuracy (the body turns soft), not stability.</source>
        <translation>Pas de région : XPBD projette les ressorts comme des contraintes souples (souplesse 1/ks) : inconditionnellement stable, aucune région dans le plan hλ ; un grand DT coûte de la précision (le corps devient mou), pas la stabilité.</translation>
    </message>
    <message>
        <source>No stability region for %1.</source>
        <translation>Pas de région de stabilité pour %1.</translation>
    </message>
</context>
<context>
    <name>elui::StrainLegend</name>
    <message>
        <source>spring strain</source>
        <translation>déformation du ressort</translation>
    </message>
</context>
<context>
    <name>elui::StudyDialogBase</name>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt; with the current parameters</source>
        <translation>Scène : &lt;b&gt;%1&lt;/b&gt; avec les paramètres actuels</translation>
    </message>
    <message>
        <source>Include %1 (order %2) in the study: %3</source>
        <translation>Inclure %1 (ordre %2) dans l’étude : %3</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Simulation</translation>
    </message>
    <message>
        <source>Run the study on a worker thread; the window stays usable</source>
        <translation>Lancer l’étude dans un fil de travail ; la fenêtre reste utilisable</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Annuler</translation>
    </message>
    <message>
        <source>Stop the study; the rows finished so far stay</source>
        <translation>Arrêter l’étude ; les lignes terminées restent</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Exporter...</translation>
    </message>
    <message>
        <source>Write the table as CSV, or the plot as SVG, PNG or PDF</source>
        <translation>Écrire le tableau en CSV, ou le graphique en SVG, PNG ou PDF</translation>
    </message>
    <message>
        <source>Study plot</source>
        <translation>Graphique de l’étude</translation>
    </message>
    <message>
        <source>The study&apos;s results drawn; the same numbers are in the table</source>
        <translation>Les résultats de l’étude en graphique ; les mêmes nombres sont dans le tableau</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Résultats</translation>
    </message>
    <message>
        <source>One row per run of the study; the arrow keys move between the cells</source>
        <translation>Une ligne par simulation de l’étude ; les flèches se déplacent entre les cellules</translation>
    </message>
    <message>
        <source>Cancelled: partial results</source>
        <translation>Annulé : résultats partiels</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Terminé</translation>
    </message>
    <message>
        <source>Choose at least one integrator</source>
        <translation>Choisissez au moins un intégrateur</translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation>Annulation...</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>Tableau CSV (*.csv);;Graphique PNG (*.png);;Graphique PDF (*.pdf)</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;SVG plot (*.svg);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>Tableau CSV (*.csv);;Graphique SVG (*.svg);;Graphique PNG (*.png);;Graphique PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export results</source>
        <translation>Exporter les résultats</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exporter</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>%1 écrit</translation>
    </message>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt;, %2 bodies, with the current parameters (the whole world: every run moves every body)</source>
        <translation>Scène : &lt;b&gt;%1&lt;/b&gt;, %2 corps, avec les paramètres actuels (le monde entier : chaque calcul déplace chaque corps)</translation>
    </message>
</context>
<context>
    <name>elui::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>Chronologie</translation>
    </message>
    <message>
        <source>|◀ Start</source>
        <translation>|◀ Début</translation>
    </message>
    <message>
        <source>The start of the recorded run (Home)</source>
        <translation>Le début de la simulation enregistrée (Début)</translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ Pas en arrière</translation>
    </message>
    <message>
        <source>One step back (Shift+S); S steps forward</source>
        <translation>Un pas en arrière (Maj+S) ; S avance d’un pas</translation>
    </message>
    <message>
        <source>Newest ▶|</source>
        <translation>Plus récent ▶|</translation>
    </message>
    <message>
        <source>The newest recorded moment (End)</source>
        <translation>L’instant enregistré le plus récent (Fin)</translation>
    </message>
    <message>
        <source>Clear abandoned</source>
        <translation>Effacer l’abandonné</translation>
    </message>
    <message>
        <source>Remove the faint lines of the abandoned future from the plots</source>
        <translation>Retirer des graphiques les traits pâles du futur abandonné</translation>
    </message>
    <message>
        <source>&lt;b&gt;Back in time&lt;/b&gt;: t = %1 s, step %2 of %3 · a change, Run or Step branches here</source>
        <translation>&lt;b&gt;Retour dans le temps&lt;/b&gt; : t = %1 s, pas %2 sur %3 · une modification, Lancer ou Pas crée une branche ici</translation>
    </message>
    <message>
        <source>t = %1 s, step %2 (newest) · recorded from t = %3 s</source>
        <translation>t = %1 s, pas %2 (le plus récent) · enregistré depuis t = %3 s</translation>
    </message>
    <message>
        <source>%1 checkpoints / %2 steps · %3 of %4</source>
        <translation>%1 points de sauvegarde / %2 pas · %3 sur %4</translation>
    </message>
    <message>
        <source>Every moment of the run: drag, or Tab to it and press the arrow keys (Page Up and Page Down: a twentieth of the run), to travel back in time (the run pauses)</source>
        <translation>Chaque instant de la simulation : faites glisser, ou atteignez-la par Tab et utilisez les flèches (Page préc. et Page suiv. : un vingtième de la simulation), pour remonter le temps (la simulation se met en pause)</translation>
    </message>
</context>
<context>
    <name>elui::Viewport</name>
    <message>
        <source>Simulation view</source>
        <translation>Vue de la simulation</translation>
    </message>
    <message>
        <source>The body. Keyboard: arrow keys or Page Up and Page Down choose a particle and show the forces on it; Enter grabs it with the mouse spring, then the arrow keys drag it (Shift: ten times farther) and Enter or Escape lets go; Escape clears the choice.</source>
        <translation>Le corps. Clavier : les flèches ou Page préc. et Page suiv. choisissent une particule et montrent les forces qui s’y appliquent ; Entrée la saisit avec le ressort de souris, puis les flèches la tirent (Maj : dix fois plus loin) et Entrée ou Échap la relâche ; Échap efface le choix.</translation>
    </message>
    <message>
        <source>Forces on particle %1</source>
        <translation>Forces sur la particule %1</translation>
    </message>
    <message>
        <source>total (sum)</source>
        <translation>total (somme)</translation>
    </message>
    <message>
        <source>arrows: 1 m = %1 N</source>
        <translation>flèches : 1 m = %1 N</translation>
    </message>
    <message>
        <source>click elsewhere to clear</source>
        <translation>cliquez ailleurs pour effacer</translation>
    </message>
    <message>
        <source>distance from %1: %2 m (RMS)</source>
        <translation>distance à %1 : %2 m (RMS)</translation>
    </message>
    <message>
        <source>Blew up at t = %1 s: %2</source>
        <translation>A explosé à t = %1 s : %2</translation>
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
        <translation>Forces sur la particule %1 du corps %2</translation>
    </message>
    <message>
        <source>momentum %1 kg m/s</source>
        <translation>quantité de mouvement %1 kg m/s</translation>
    </message>
    <message>
        <source>min_gap %1 m</source>
        <translation>min_gap %1 m</translation>
    </message>
    <message>
        <source>min_gap beyond %1 m</source>
        <translation>min_gap au-delà de %1 m</translation>
    </message>
</context>
<context>
    <name>elui::WorkPrecisionDialog</name>
    <message>
        <source>Work-precision study</source>
        <translation>Étude travail-précision</translation>
    </message>
    <message>
        <source>Fixed steps DT [s], separated by spaces; T must be a multiple of each</source>
        <translation>Pas fixes DT [s], séparés par des espaces ; T doit être un multiple de chacun</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Temps simulé de chaque simulation [s]</translation>
    </message>
    <message>
        <source>What the errors are measured against: the closed form where there is one (exact), or a run of rk4 or rk45 with a much smaller step; auto chooses</source>
        <translation>Ce contre quoi les erreurs sont mesurées : la solution exacte quand il y en a une (exact), ou une simulation rk4 ou rk45 avec un pas bien plus petit ; auto choisit</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Référence</translation>
    </message>
    <message>
        <source>Each point is timed this many times; the plot shows the median run time with a band from the first to the third quartile (the same binary runs at two speeds on a shared machine)</source>
        <translation>Chaque point est chronométré autant de fois ; le graphique montre le temps de calcul médian avec une bande du premier au troisième quartile (le même programme tourne à deux vitesses sur une machine partagée)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>aucun</translation>
    </message>
    <message>
        <source>A run that takes longer [s] is recorded as not reached (no error), and so is every costlier point of its integrator: the curve stops there</source>
        <translation>Une simulation plus longue [s] est notée non atteinte (sans erreur), de même que chaque point plus coûteux de son intégrateur : la courbe s’arrête là</translation>
    </message>
    <message>
        <source>DT values [s]</source>
        <translation>Valeurs de DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Durée T [s]</translation>
    </message>
    <message>
        <source>Timed runs per point</source>
        <translation>Simulations chronométrées par point</translation>
    </message>
    <message>
        <source>Time budget per run [s]</source>
        <translation>Budget de temps par simulation [s]</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>évaluations de force</translation>
    </message>
    <message>
        <source>run time (median, band q1–q3)</source>
        <translation>temps de calcul (médiane, bande q1–q3)</translation>
    </message>
    <message>
        <source>The cost of a run on the left panel: the force evaluations it took (a count: the same on every machine and every run), or its run time, the median over the timed runs with a band from q1 to q3 (on a busy machine a curve can zigzag backwards)</source>
        <translation>Le coût d’une simulation dans le panneau de gauche : le nombre d’évaluations de force (identique sur toute machine et à chaque simulation), ou son temps de calcul, la médiane des simulations chronométrées avec une bande de q1 à q3 (sur une machine chargée, une courbe peut zigzaguer en arrière)</translation>
    </message>
    <message>
        <source>Cost axis</source>
        <translation>Axe du coût</translation>
    </message>
    <message>
        <source>max position error [m]</source>
        <translation>erreur max. de position [m]</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>run time [s] (median, band q1–q3)</source>
        <translation>temps de calcul [s] (médiane, bande q1–q3)</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>intégrateur</translation>
    </message>
    <message>
        <source>family</source>
        <translation>famille</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pas</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>éval. de force</translation>
    </message>
    <message>
        <source>run time q1 [s]</source>
        <translation>temps q1 [s]</translation>
    </message>
    <message>
        <source>median [s]</source>
        <translation>médiane [s]</translation>
    </message>
    <message>
        <source>q3 [s]</source>
        <translation>q3 [s]</translation>
    </message>
    <message>
        <source>error at T [m]</source>
        <translation>erreur à T [m]</translation>
    </message>
    <message>
        <source>max error [m]</source>
        <translation>erreur max. [m]</translation>
    </message>
    <message>
        <source>RMS error [m]</source>
        <translation>erreur RMS [m]</translation>
    </message>
    <message>
        <source>energy error [J]</source>
        <translation>erreur d’énergie [J]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>état</translation>
    </message>
    <message>
        <source>Reference: %1 (its own error about %2 m). Run time: median of %3 timed runs per point, band q1–q3.</source>
        <translation>Référence : %1 (sa propre erreur environ %2 m). Temps de calcul : médiane de %3 simulations chronométrées par point, bande q1–q3.</translation>
    </message>
    <message>
        <source> %1: order %2 (RMS %3).</source>
        <translation> %1 : ordre %2 (RMS %3).</translation>
    </message>
    <message>
        <source> q1–q3</source>
        <translation> q1–q3</translation>
    </message>
    <message>
        <source>fastest of its family</source>
        <translation>le plus rapide de sa famille</translation>
    </message>
</context>
<context>
    <name>simcore</name>
    <message>
        <source>structural spring stiffness KS, per spring (scaling=physical: at the reference resolution; a 2D chain keeps k L0, a 3D membrane keeps k)</source>
        <translation>raideur KS des ressorts structurels, par ressort (scaling=physical : à la résolution de référence ; une chaîne 2D conserve k L0, une membrane 3D conserve k)</translation>
    </message>
    <message>
        <source>structural spring damping KD, per spring; scales like KS</source>
        <translation>amortissement KD des ressorts structurels, par ressort ; varie comme KS</translation>
    </message>
    <message>
        <source>radius and shear spring stiffness RKS, per spring (scaling=physical: at the reference resolution; in parallel, k times count stays fixed)</source>
        <translation>raideur RKS des ressorts radiaux et de cisaillement, par ressort (scaling=physical : à la résolution de référence ; en parallèle, k fois le nombre reste fixe)</translation>
    </message>
    <message>
        <source>radius and shear spring damping RKD, per spring; scales like RKS</source>
        <translation>amortissement RKD des ressorts radiaux et de cisaillement, par ressort ; varie comme RKS</translation>
    </message>
    <message>
        <source>gas constant nRT of each closed layer (PRESSURE): P = nRT / V</source>
        <translation>constante du gaz nRT de chaque couche fermée (PRESSURE) : P = nRT / V</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the inner layer (defaults to pressure)</source>
        <translation>nRT du gaz enfermé par la couche intérieure (par défaut : pressure)</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the outer layer (defaults to pressure)</source>
        <translation>nRT du gaz enfermé par la couche extérieure (par défaut : pressure)</translation>
    </message>
    <message>
        <source>particle mass MASS (scaling=physical: at the reference resolution; each layer keeps its total)</source>
        <translation>masse d’une particule MASS (scaling=physical : à la résolution de référence ; chaque couche conserve sa masse totale)</translation>
    </message>
    <message>
        <source>inner-layer particle mass (defaults to mass; scaled like mass): real inertia, not scaled gravity</source>
        <translation>masse d’une particule de la couche intérieure (par défaut : mass ; varie comme mass) : une vraie inertie, pas une pesanteur modifiée</translation>
    </message>
    <message>
        <source>outer-layer particle mass (defaults to mass; scaled like mass)</source>
        <translation>masse d’une particule de la couche extérieure (par défaut : mass ; varie comme mass)</translation>
    </message>
    <message>
        <source>gravitational acceleration, pointing along -y</source>
        <translation>accélération de la pesanteur, dirigée selon -y</translation>
    </message>
    <message>
        <source>half-size of the collision box (floor, ceiling, walls), centred on the body&apos;s start</source>
        <translation>demi-côté de la boîte de collision (sol, plafond, parois), centrée sur la position de départ du corps</translation>
    </message>
    <message>
        <source>contact model: 0 = force (smooth penalty force inside the ODE, in the energy ledger), 1 = projection (the thesis program: put back and reflect after the step)</source>
        <translation>modèle de contact : 0 = force (force de pénalité régulière dans l’EDO, comptée dans le bilan d’énergie), 1 = projection (le programme du mémoire : replacer et réfléchir après le pas)</translation>
    </message>
    <message>
        <source>coefficient of restitution e at the box walls: a particle hitting at contact_speed rebounds at e times its speed (projection: v_n becomes -e*v_n)</source>
        <translation>coefficient de restitution e aux parois de la boîte : une particule qui frappe à contact_speed rebondit à e fois sa vitesse (projection : v_n devient -e*v_n)</translation>
    </message>
    <message>
        <source>k of the contact potential U = k d^4/4 per particle at a wall (d: penetration) and of the layer barrier (scaling=physical: at the reference resolution, scaled like mass)</source>
        <translation>k du potentiel de contact U = k d^4/4 par particule à une paroi (d : pénétration) et de la barrière entre couches (scaling=physical : à la résolution de référence, varie comme mass)</translation>
    </message>
    <message>
        <source>impact speed at which the contact damping gives exactly the restitution e</source>
        <translation>vitesse d’impact pour laquelle l’amortissement de contact donne exactement la restitution e</translation>
    </message>
    <message>
        <source>wall friction: Coulomb coefficient mu (force); tangential velocity fraction removed (projection)</source>
        <translation>frottement aux parois : coefficient de Coulomb mu (force) ; fraction de la vitesse tangentielle retirée (projection)</translation>
    </message>
    <message>
        <source>slip speed below which Coulomb friction is smoothed (regularised) [force contact]</source>
        <translation>vitesse de glissement sous laquelle le frottement de Coulomb est lissé (régularisé) [contact force]</translation>
    </message>
    <message>
        <source>mouse spring stiffness (MKS)</source>
        <translation>raideur du ressort de souris (MKS)</translation>
    </message>
    <message>
        <source>mouse spring damping (MKD)</source>
        <translation>amortissement du ressort de souris (MKD)</translation>
    </message>
    <message>
        <source>rest length of the mouse spring</source>
        <translation>longueur au repos du ressort de souris</translation>
    </message>
    <message>
        <source>time step DT of fixed-step integrators (initial step of adaptive ones)</source>
        <translation>pas de temps DT des intégrateurs à pas fixe (pas initial des adaptatifs)</translation>
    </message>
    <message>
        <source>xpbd: substeps per step DT, one constraint iteration each (Macklin et al. 2019, small steps)</source>
        <translation>xpbd : sous-pas par pas DT, une itération des contraintes chacun (Macklin et al. 2019, petits pas)</translation>
    </message>
    <message>
        <source>what mass, ks, kd, rks, rkd and contact_stiffness mean when the mesh is refined: 0 = physical (the values hold at the scene&apos;s default resolution and the body keeps its totals and material constants), 1 = thesis (per particle and per spring at every resolution)</source>
        <translation>ce que signifient mass, ks, kd, rks, rkd et contact_stiffness quand le maillage est raffiné : 0 = physical (les valeurs valent pour la résolution par défaut de la scène et le corps conserve ses totaux et ses constantes de matériau), 1 = thesis (par particule et par ressort à toute résolution)</translation>
    </message>
    <message>
        <source>particles per layer of the 2D ring</source>
        <translation>particules par couche de l’anneau 2D</translation>
    </message>
    <message>
        <source>subdivision level L of the octahedron sphere: 4*4^L+2 particles per layer</source>
        <translation>niveau de subdivision L de la sphère octaédrique : 4*4^L+2 particules par couche</translation>
    </message>
    <message>
        <source>meridians of the lat/long sphere</source>
        <translation>méridiens de la sphère en longitude/latitude</translation>
    </message>
    <message>
        <source>latitude bands of the lat/long sphere (pole to pole)</source>
        <translation>bandes de latitude de la sphère en longitude/latitude (d’un pôle à l’autre)</translation>
    </message>
    <message>
        <source>rest radius of the inner layer (must be below radius_outer)</source>
        <translation>rayon au repos de la couche intérieure (doit être inférieur à radius_outer)</translation>
    </message>
    <message>
        <source>rest radius of the outer layer</source>
        <translation>rayon au repos de la couche extérieure</translation>
    </message>
    <message>
        <source>rest length of the 1D spring</source>
        <translation>longueur au repos du ressort 1D</translation>
    </message>
    <message>
        <source>distance between the two particles at the start (the spring hangs along -y)</source>
        <translation>distance entre les deux particules au départ (le ressort pend selon -y)</translation>
    </message>
    <message>
        <source>1: the top particle is fixed in space (thesis fig. 7); 0: both particles move</source>
        <translation>1 : la particule du haut est fixe dans l’espace (mémoire, fig. 7) ; 0 : les deux particules bougent</translation>
    </message>
    <message>
        <source>amplitude of a seeded random displacement of the start positions (breaks symmetry)</source>
        <translation>amplitude d’un déplacement aléatoire (graine fixée) des positions de départ (brise la symétrie)</translation>
    </message>
    <message>
        <source>seed of the start perturbation</source>
        <translation>graine de la perturbation de départ</translation>
    </message>
    <message>
        <source>1D: two masses on one spring hanging along -y, the top one fixed (thesis fig. 7)</source>
        <translation>1D : deux masses sur un ressort suspendu selon -y, celle du haut fixe (mémoire, fig. 7)</translation>
    </message>
    <message>
        <source>2D: two concentric gas-filled rings joined by radius and shear springs (thesis 3.4)</source>
        <translation>2D : deux anneaux concentriques remplis de gaz, reliés par des ressorts radiaux et de cisaillement (mémoire 3.4)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled spheres, subdivided octahedron (thesis 3.5.2)</source>
        <translation>3D : deux sphères concentriques remplies de gaz, octaèdre subdivisé (mémoire 3.5.2)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled lat/long spheres, the non-uniform sphere (thesis 3.5.1)</source>
        <translation>3D : deux sphères concentriques remplies de gaz en longitude/latitude, la sphère non uniforme (mémoire 3.5.1)</translation>
    </message>
    <message>
        <source>explicit Euler: x and v both from the old state (thesis eq. 22)</source>
        <translation>Euler explicite : x et v tous deux à partir de l’ancien état (mémoire, éq. 22)</translation>
    </message>
    <message>
        <source>the thesis&apos;s midpoint (eq. 31-33), i.e. Heun&apos;s RK2: two force evaluations</source>
        <translation>le point milieu du mémoire (éq. 31-33), c’est-à-dire le RK2 de Heun : deux évaluations de force</translation>
    </message>
    <message>
        <source>classical Runge-Kutta 4 (eq. 35-40): four force evaluations</source>
        <translation>Runge-Kutta 4 classique (éq. 35-40) : quatre évaluations de force</translation>
    </message>
    <message>
        <source>semi-implicit Euler: v from the old forces, then x from the new v</source>
        <translation>Euler semi-implicite : v à partir des anciennes forces, puis x à partir du nouveau v</translation>
    </message>
    <message>
        <source>velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)</source>
        <translation>Verlet vitesse (ordre 1 quand l’amortissement est actif : l’amortissement est pris à la vitesse du demi-pas)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 4th-order composition of velocity Verlet: 3 substeps (one backwards), 4 force evaluations (order 1 with damping)</source>
        <translation>composition d’ordre 4 de Yoshida à partir de Verlet vitesse : 3 sous-pas (dont un en arrière), 4 évaluations de force (ordre 1 avec amortissement)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 8th-order composition of velocity Verlet (solution D): 15 substeps, 16 force evaluations (order 1 with damping)</source>
        <translation>composition d’ordre 8 de Yoshida à partir de Verlet vitesse (solution D) : 15 sous-pas, 16 évaluations de force (ordre 1 avec amortissement)</translation>
    </message>
    <message>
        <source>Dormand-Prince 5(4): adaptive step from atol/rtol, embedded error estimate every step</source>
        <translation>Dormand-Prince 5(4) : pas adaptatif à partir d’atol/rtol, estimation d’erreur emboîtée à chaque pas</translation>
    </message>
    <message>
        <source>linearised backward Euler (Baraff-Witkin 1998): spring and gas Jacobians, matrix-free CG</source>
        <translation>Euler implicite linéarisé (Baraff-Witkin 1998) : jacobiennes des ressorts et du gaz, gradient conjugué sans matrice</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order BDF 1-5: Newton, matrix-free GMRES on the analytic Jacobian, implicit-euler&apos;s solve as preconditioner; adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, BDF d’ordre variable 1-5 : Newton, GMRES sans matrice sur la jacobienne analytique, la résolution d’implicit-euler comme préconditionneur ; adaptatif à partir d’atol/rtol</translation>
    </message>
    <message>
        <source>extended position-based dynamics (Macklin et al. 2016, small steps 2019): springs as compliant distance constraints, `substeps` substeps of one iteration per step</source>
        <translation>dynamique basée sur les positions étendue (Macklin et al. 2016, petits pas 2019) : ressorts comme contraintes de distance souples, `substeps` sous-pas d’une itération par pas</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order Adams-Moulton 1-12 with fixed-point iteration (non-stiff); adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, Adams-Moulton d’ordre variable 1-12 avec itération de point fixe (non raide) ; adaptatif à partir d’atol/rtol</translation>
    </message>
</context>
</TS>
