<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="es">
<context>
    <name>FailureText</name>
    <message>
        <source>the inner layer</source>
        <translation>la capa interior</translation>
    </message>
    <message>
        <source>the outer layer</source>
        <translation>la capa exterior</translation>
    </message>
    <message>
        <source>the layer</source>
        <translation>la capa</translation>
    </message>
    <message>
        <source>%1 turned inside out (its area is %2, rest %3)</source>
        <translation>%1 se dio la vuelta (su área es %2, en reposo %3)</translation>
    </message>
    <message>
        <source>%1 turned inside out (its volume is %2, rest %3)</source>
        <translation>%1 se dio la vuelta (su volumen es %2, en reposo %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its area is %2, rest %3)</source>
        <translation>%1 colapsó (su área es %2, en reposo %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its volume is %2, rest %3)</source>
        <translation>%1 colapsó (su volumen es %2, en reposo %3)</translation>
    </message>
    <message>
        <source>body %1: %2</source>
        <translation>cuerpo %1: %2</translation>
    </message>
    <message>
        <source>the state became non-finite (NaN or infinity): the step is far too large for these forces</source>
        <translation>el estado dejó de ser finito (NaN o infinito): el paso es demasiado grande para estas fuerzas</translation>
    </message>
    <message>
        <source>rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too stiff or singular)</source>
        <translation>rk45: el paso cayó por debajo del paso mínimo; la tolerancia no se puede cumplir (el sistema es demasiado rígido o singular)</translation>
    </message>
    <message>
        <source>implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is not positive definite at this step (the body is too deformed or the step too large)</source>
        <translation>implicit-euler: la resolución lineal (gradiente conjugado) no convergió; el sistema linealizado no es definido positivo en este paso (el cuerpo está demasiado deformado o el paso es demasiado grande)</translation>
    </message>
    <message>
        <source>runaway velocity: a particle moves %1 m/s, farther than the whole box in one step</source>
        <translation>velocidad desbocada: una partícula se mueve a %1 m/s, más que toda la caja en un paso</translation>
    </message>
    <message>
        <source>runaway energy: kinetic + elastic energy %1 J exceeds %2 J (%3 × the body&apos;s energy scale)</source>
        <translation>energía desbocada: la energía cinética + elástica, %1 J, supera %2 J (%3 × la escala de energía del cuerpo)</translation>
    </message>
    <message>
        <source>the state is no longer finite (particle %1)</source>
        <translation>el estado ya no es finito (partícula %1)</translation>
    </message>
    <message>
        <source>particle %1 reached a wall: the float path has no contact (use precision double)</source>
        <translation>la partícula %1 llegó a una pared: el cálculo en float no tiene contacto (elija la precisión double)</translation>
    </message>
    <message>
        <source>body %1&apos;s outer layer passed through itself in a step of %2 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>la capa exterior del cuerpo %1 se atravesó a sí misma en un paso de %2 s: el paso es demasiado grande para este choque (un dt menor, o un integrador adaptativo, que divide ese paso por dos)</translation>
    </message>
    <message>
        <source>bodies %1 and %2 intersect (their outer layers crossed) in a step of %3 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>los cuerpos %1 y %2 se interpenetran (sus capas exteriores se cruzaron) en un paso de %3 s: el paso es demasiado grande para este choque (un dt menor, o un integrador adaptativo, que divide ese paso por dos)</translation>
    </message>
    <message>
        <source>exact spectrum, %1 eigenvalues</source>
        <translation>espectro exacto, %1 valores propios</translation>
    </message>
    <message>
        <source>Arnoldi, %1 Ritz values of %2</source>
        <translation>Arnoldi, %1 valores de Ritz de %2</translation>
    </message>
    <message>
        <source>exact step matrix</source>
        <translation>matriz de paso exacta</translation>
    </message>
    <message>
        <source>modes of M^-1 K</source>
        <translation>modos de M^-1 K</translation>
    </message>
    <message>
        <source>%1 chooses its own step: no DT limit from stability</source>
        <translation>%1 elige su propio paso: la estabilidad no limita DT</translation>
    </message>
    <message>
        <source>%1 is stable at every DT on this body</source>
        <translation>%1 es estable con cualquier DT en este cuerpo</translation>
    </message>
    <message>
        <source>%1 has no stable DT on this body: its undamped modes grow for every DT (%2)</source>
        <translation>%1 no tiene DT estable en este cuerpo: sus modos no amortiguados crecen con cualquier DT (%2)</translation>
    </message>
    <message>
        <source>%1 is stable up to DT = %2 s on this body (%3)</source>
        <translation>%1 es estable hasta DT = %2 s en este cuerpo (%3)</translation>
    </message>
    <message>
        <source>%1 has no stable step on this body&apos;s undamped modes (highest w = %2 rad/s): its energy grows for every dt, here by ~%3 per second; use dt &lt;= %4 s (growth below 1 per second) or another method</source>
        <translation>%1 no tiene paso estable en los modos no amortiguados de este cuerpo (w más alta = %2 rad/s): su energía crece con cualquier dt, aquí ~%3 por segundo; use dt &lt;= %4 s (crecimiento por debajo de 1 por segundo) u otro método</translation>
    </message>
    <message>
        <source>dt = %1 s is above %2&apos;s largest stable step on this body, %3 s (linearised: %4; fastest |lambda| = %5 1/s); it will likely blow up (implicit-euler or rk45 will not)</source>
        <translation>dt = %1 s supera el mayor paso estable de %2 en este cuerpo, %3 s (linealizado: %4; |lambda| más rápido = %5 1/s); probablemente explotará (implicit-euler o rk45 no)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>solid</source>
        <translation>continua</translation>
    </message>
    <message>
        <source>hatched</source>
        <translation>rayada</translation>
    </message>
    <message>
        <source>dotted</source>
        <translation>punteada</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>No se pudo abrir %1: %2</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>No se pudo escribir %1: %2</translation>
    </message>
    <message>
        <source>the data was not written completely</source>
        <translation>los datos no se escribieron por completo</translation>
    </message>
    <message>
        <source>Could not encode %1 as %2</source>
        <translation>No se pudo codificar %1 como %2</translation>
    </message>
    <message>
        <source>No plot to export</source>
        <translation>No hay gráfico que exportar</translation>
    </message>
    <message>
        <source>Could not encode %1</source>
        <translation>No se pudo codificar %1</translation>
    </message>
    <message>
        <source>Three Verlet substeps (the middle one backwards): fourth order, and energy stays bounded like Verlet&apos;s; stable up to h·ω ≈ 1.57 on an undamped spring.</source>
        <translation>Tres subpasos de Verlet (el del medio hacia atrás): cuarto orden, y la energía se mantiene acotada como con Verlet; estable hasta h·ω ≈ 1,57 en un resorte sin amortiguar.</translation>
    </message>
    <message>
        <source>Fifteen Verlet substeps: eighth order for undamped bodies, the error reaches round-off at moderate steps; 16 force evaluations a step.</source>
        <translation>Quince subpasos de Verlet: octavo orden para cuerpos sin amortiguar, el error alcanza el redondeo con pasos moderados; 16 evaluaciones de fuerza por paso.</translation>
    </message>
    <message>
        <source>Chooses its own step to meet a tolerance; the readout shows its error estimate.</source>
        <translation>Elige su propio paso para cumplir una tolerancia; la lectura muestra su estimación del error.</translation>
    </message>
    <message>
        <source>Stable at any DT (it damps instead of blowing up): the one to use for DT 0.3.</source>
        <translation>Estable con cualquier DT (amortigua en vez de explotar): el que hay que usar con DT 0,3.</translation>
    </message>
    <message>
        <source>A production stiff solver (SUNDIALS): wins where stiffness is damping (overdamped springs), not where it is fast oscillation, which it must still follow.</source>
        <translation>Un resolvedor rígido de producción (SUNDIALS): gana donde la rigidez viene del amortiguamiento (resortes sobreamortiguados), no donde es una oscilación rápida, que igualmente debe seguir.</translation>
    </message>
    <message>
        <source>A production non-stiff solver (SUNDIALS): high order, few force evaluations per step.</source>
        <translation>Un resolvedor no rígido de producción (SUNDIALS): orden alto, pocas evaluaciones de fuerza por paso.</translation>
    </message>
    <message>
        <source>The game-physics way (Jolt, PhysX): stable at DT 1/60 on stiff springs, but it removes energy the body never lost; more substeps, less loss.</source>
        <translation>El método de la física de videojuegos (Jolt, PhysX): estable con DT 1/60 en resortes rígidos, pero quita energía que el cuerpo nunca perdió; más subpasos, menos pérdida.</translation>
    </message>
    <message>
        <source>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;A two-layer elastic body: particles joined by springs, with gas inside each closed layer. Drag the body with the mouse; change any parameter while it runs.&lt;/p&gt;</source>
        <translation>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;Un cuerpo elástico de dos capas: partículas unidas por resortes, con gas dentro de cada capa cerrada. Arrastre el cuerpo con el ratón; cambie cualquier parámetro mientras corre.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;The model&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Particles&lt;/b&gt; carry mass; gravity pulls along −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Springs&lt;/b&gt; (Hooke + damping): &lt;i&gt;structural&lt;/i&gt; springs along each layer (KS, KD), &lt;i&gt;radius&lt;/i&gt; springs between paired inner and outer particles and &lt;i&gt;shear&lt;/i&gt; springs across them (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: each closed layer encloses gas with P = nRT / V, pushing outward on every edge (2D) or face (3D). V is the exact area or volume.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mouse spring&lt;/b&gt; (MKS, MKD) from the pointer to the grabbed particle.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Contact&lt;/b&gt; is a smooth force inside the equations of motion: a particle that sinks a depth d into a wall is pushed back by k d³ (contact energy k d⁴/4), damped so that one hitting at contact_speed rebounds with the restitution e, with smooth Coulomb friction, and a barrier of the same kind keeps the inner layer inside the outer one. contact = projection restores the thesis program instead, which puts a particle back and reverses its normal speed after each step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resolution&lt;/b&gt; (Scene dock): with scaling = physical the masses and spring constants hold at the scene&apos;s default mesh, and a finer mesh keeps the body&apos;s totals (layer mass, material stiffness), so it is the same body, only finer; scaling = thesis makes them per particle and per spring at every mesh. A finer body has faster modes and needs a smaller DT: the window offers one when a rebuild needs it.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;The plots show the energy book: kinetic + spring + gravity + gas + contact is the total; what damping and contact take out is &apos;removed&apos;. For an exact integrator, total + removed − work by the mouse stays constant; the readout&apos;s &lt;i&gt;energy drift&lt;/i&gt; is how far it is off.&lt;/p&gt;&lt;p&gt;View → &lt;b&gt;Energy bars&lt;/b&gt; shows the same book as bars, one per term, in the plot&apos;s colours, with the drift last. View → &lt;b&gt;P–V diagram&lt;/b&gt; shows each gas layer&apos;s pressure against its volume: the trail lies on the isotherm P = nRT / V, drawn dashed.&lt;/p&gt;</source>
        <translation>&lt;h3&gt;El modelo&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Las &lt;b&gt;partículas&lt;/b&gt; tienen masa; la gravedad tira a lo largo de −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resortes&lt;/b&gt; (Hooke + amortiguamiento): resortes &lt;i&gt;estructurales&lt;/i&gt; a lo largo de cada capa (KS, KD), resortes &lt;i&gt;radiales&lt;/i&gt; entre partículas interiores y exteriores emparejadas y resortes de &lt;i&gt;cizalla&lt;/i&gt; cruzados (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: cada capa cerrada encierra gas con P = nRT / V, que empuja hacia fuera en cada arista (2D) o cara (3D). V es el área o el volumen exacto.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resorte del ratón&lt;/b&gt; (MKS, MKD) del puntero a la partícula agarrada.&lt;/li&gt;&lt;li&gt;El &lt;b&gt;contacto&lt;/b&gt; es una fuerza suave dentro de las ecuaciones del movimiento: una partícula que se hunde una profundidad d en una pared es empujada de vuelta con k d³ (energía de contacto k d⁴/4), amortiguada de modo que una que choca a contact_speed rebota con el coeficiente de restitución e, con rozamiento de Coulomb suavizado, y una barrera del mismo tipo mantiene la capa interior dentro de la exterior. contact = projection restablece en su lugar el programa de la tesis, que recoloca la partícula e invierte su velocidad normal tras cada paso.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resolución&lt;/b&gt; (panel Escena): con scaling = physical las masas y constantes de los resortes valen para la malla por defecto de la escena, y una malla más fina conserva los totales del cuerpo (masa de la capa, rigidez del material): es el mismo cuerpo, solo más fino; scaling = thesis las hace por partícula y por resorte en cualquier malla. Un cuerpo más fino tiene modos más rápidos y necesita un DT menor: la ventana ofrece uno cuando una reconstrucción lo requiere.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;Los gráficos muestran el balance de energía: cinética + resorte + gravedad + gas + contacto es el total; lo que el amortiguamiento y el contacto quitan es «quitado». Para un integrador exacto, total + quitado − trabajo del ratón se mantiene constante; la &lt;i&gt;deriva de energía&lt;/i&gt; de la lectura dice cuánto se aparta.&lt;/p&gt;&lt;p&gt;Ver → &lt;b&gt;Barras de energía&lt;/b&gt; muestra el mismo balance en barras, una por término, con los colores del gráfico y la deriva al final. Ver → &lt;b&gt;Diagrama P–V&lt;/b&gt; muestra la presión de cada capa de gas frente a su volumen: la traza está sobre la isoterma P = nRT / V, dibujada a trazos.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Integrators&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;name&lt;/th&gt;&lt;th&gt;order&lt;/th&gt;&lt;th&gt;what it does&lt;/th&gt;&lt;th&gt;in class&lt;/th&gt;&lt;/tr&gt;</source>
        <translation>&lt;h3&gt;Integradores&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;nombre&lt;/th&gt;&lt;th&gt;orden&lt;/th&gt;&lt;th&gt;qué hace&lt;/th&gt;&lt;th&gt;en clase&lt;/th&gt;&lt;/tr&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Presets&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Ajustes predefinidos&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;Mouse&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Left-drag on the body: grab the nearest outer particle and pull it.&lt;/li&gt;&lt;li&gt;Left-drag elsewhere, or Shift+left-drag (3D): orbit. Right- or middle-drag: pan. Wheel: zoom. View → Reset view.&lt;/li&gt;&lt;/ul&gt;</source>
        <translation>&lt;h3&gt;Ratón&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Arrastrar con el botón izquierdo sobre el cuerpo: agarrar la partícula exterior más cercana y tirar de ella.&lt;/li&gt;&lt;li&gt;Arrastrar con el izquierdo en otro lugar, o Mayús+arrastrar (3D): girar. Arrastrar con el derecho o el central: desplazar. Rueda: zoom. Ver → Restablecer vista.&lt;/li&gt;&lt;/ul&gt;</translation>
    </message>
    <message>
        <source>&lt;h3&gt;More&lt;/h3&gt;&lt;ul&gt;</source>
        <translation>&lt;h3&gt;Más&lt;/h3&gt;&lt;ul&gt;</translation>
    </message>
    <message>
        <source>The GUI (docs/gui.md)</source>
        <translation>La interfaz (docs/gui.md)</translation>
    </message>
    <message>
        <source>Architecture (docs/architecture.md)</source>
        <translation>Arquitectura (docs/architecture.md)</translation>
    </message>
    <message>
        <source>README</source>
        <translation>README</translation>
    </message>
    <message>
        <source>1. How large may DT be for Euler?</source>
        <translation>1. ¿Qué tamaño puede tener DT con Euler?</translation>
    </message>
    <message>
        <source>2. Energy drift: Euler, midpoint, RK4</source>
        <translation>2. Deriva de energía: Euler, punto medio, RK4</translation>
    </message>
    <message>
        <source>3. A heavy inner layer: liquid motion</source>
        <translation>3. Una capa interior pesada: movimiento de líquido</translation>
    </message>
    <message>
        <source>4. A finer sphere needs a smaller DT</source>
        <translation>4. Una esfera más fina necesita un DT menor</translation>
    </message>
    <message>
        <source>5. Pressure and volume on the isotherm</source>
        <translation>5. Presión y volumen sobre la isoterma</translation>
    </message>
    <message>
        <source>6. Restitution: a particle and a body</source>
        <translation>6. Restitución: una partícula y un cuerpo</translation>
    </message>
    <message>
        <source>7. Stiff springs: explicit against implicit</source>
        <translation>7. Resortes rígidos: explícito frente a implícito</translation>
    </message>
    <message>
        <source>8. Why symplectic? Energy over ten thousand periods</source>
        <translation>8. ¿Por qué simpléctico? La energía a lo largo de diez mil periodos</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>Objetivo</translation>
    </message>
    <message>
        <source>What to do</source>
        <translation>Qué hacer</translation>
    </message>
    <message>
        <source>What to look at</source>
        <translation>Qué observar</translation>
    </message>
    <message>
        <source>The measured answer</source>
        <translation>La respuesta medida</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>Por qué</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>Resortes</translation>
    </message>
    <message>
        <source>Gas</source>
        <translation>Gas</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>Masa</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>Entorno</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>Contacto</translation>
    </message>
    <message>
        <source>Mouse spring</source>
        <translation>Resorte del ratón</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>Tiempo</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>Forma</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <source>gas nRT</source>
        <translation>gas nRT</translation>
    </message>
    <message>
        <source>gas nRT inner</source>
        <translation>gas nRT interior</translation>
    </message>
    <message>
        <source>gas nRT outer</source>
        <translation>gas nRT exterior</translation>
    </message>
    <message>
        <source>Area per layer</source>
        <translation>Área por capa</translation>
    </message>
    <message>
        <source>Volume per layer</source>
        <translation>Volumen por capa</translation>
    </message>
    <message>
        <source>area [m²]</source>
        <translation>área [m²]</translation>
    </message>
    <message>
        <source>volume [m³]</source>
        <translation>volumen [m³]</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>interior</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>exterior</translation>
    </message>
    <message>
        <source>Pressure per layer</source>
        <translation>Presión por capa</translation>
    </message>
    <message>
        <source>pressure [N/m]</source>
        <translation>presión [N/m]</translation>
    </message>
    <message>
        <source>pressure [Pa]</source>
        <translation>presión [Pa]</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>Energía</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>energía [J]</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>cinética</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>resorte</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>gravedad</translation>
    </message>
    <message>
        <source>gas</source>
        <translation>gas</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>contacto</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>quitado</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>quitado por el contacto</translation>
    </message>
    <message>
        <source>spring: structural</source>
        <translation>resorte: estructural</translation>
    </message>
    <message>
        <source>spring: radius</source>
        <translation>resorte: radial</translation>
    </message>
    <message>
        <source>spring: shear</source>
        <translation>resorte: cizalla</translation>
    </message>
    <message>
        <source>mouse spring</source>
        <translation>resorte del ratón</translation>
    </message>
    <message>
        <source>removed by damping</source>
        <translation>quitado por el amortiguamiento</translation>
    </message>
    <message>
        <source>removed by projection</source>
        <translation>quitado por la proyección</translation>
    </message>
    <message>
        <source>drift (balance error)</source>
        <translation>deriva (error del balance)</translation>
    </message>
    <message>
        <source>1D drop: two masses on a spring</source>
        <translation>Caída 1D: dos masas en un resorte</translation>
    </message>
    <message>
        <source>Both masses fall, hit the floor and bounce; the spring oscillates (thesis fig. 7).</source>
        <translation>Ambas masas caen, chocan con el suelo y rebotan; el resorte oscila (tesis, fig. 7).</translation>
    </message>
    <message>
        <source>1D hanging spring</source>
        <translation>Resorte colgante 1D</translation>
    </message>
    <message>
        <source>The top mass is fixed; the lower one oscillates around the stretched rest length.</source>
        <translation>La masa de arriba está fija; la de abajo oscila en torno a la longitud de reposo estirada.</translation>
    </message>
    <message>
        <source>2D ring</source>
        <translation>Anillo 2D</translation>
    </message>
    <message>
        <source>Two gas-filled rings joined by radius and shear springs drop onto the floor (thesis 3.4).</source>
        <translation>Dos anillos llenos de gas unidos por resortes radiales y de cizalla caen al suelo (tesis 3.4).</translation>
    </message>
    <message>
        <source>3D sphere</source>
        <translation>Esfera 3D</translation>
    </message>
    <message>
        <source>Two gas-filled spheres (subdivided octahedron) drop and bounce (thesis 3.5.2).</source>
        <translation>Dos esferas llenas de gas (octaedro subdividido) caen y rebotan (tesis 3.5.2).</translation>
    </message>
    <message>
        <source>3D lat/long sphere (non-uniform)</source>
        <translation>Esfera 3D de longitud/latitud (no uniforme)</translation>
    </message>
    <message>
        <source>The lat/long sphere: particles crowd at the poles, so the body is not uniform (thesis 3.5.1).</source>
        <translation>La esfera de longitud/latitud: las partículas se amontonan en los polos, así que el cuerpo no es uniforme (tesis 3.5.1).</translation>
    </message>
    <message>
        <source>Heavy inner layer (non-uniform density)</source>
        <translation>Capa interior pesada (densidad no uniforme)</translation>
    </message>
    <message>
        <source>The inner layer is five times heavier: it sinks inside the outer one and the body lands bottom-heavy (thesis 8.1).</source>
        <translation>La capa interior es cinco veces más pesada: se hunde dentro de la exterior y el cuerpo aterriza con el peso abajo (tesis 8.1).</translation>
    </message>
    <message>
        <source>Liquid motion and inertia</source>
        <translation>Movimiento de líquido e inercia</translation>
    </message>
    <message>
        <source>Inner and outer layers pushed in opposite directions (3 m/s), without gravity and with soft, lightly damped radius and shear springs: the inner layer sloshes inside the outer one like a liquid (thesis fig. 47).</source>
        <translation>Capas interior y exterior empujadas en sentidos opuestos (3 m/s), sin gravedad y con resortes radiales y de cizalla blandos y poco amortiguados: la capa interior chapotea dentro de la exterior como un líquido (tesis, fig. 47).</translation>
    </message>
    <message>
        <source>Stability experiment, DT = %1 s</source>
        <translation>Experimento de estabilidad, DT = %1 s</translation>
    </message>
    <message>
        <source>Euler, midpoint and RK4 from the same start at DT = %1 s (thesis 7.2.2, figs. 41-43). Watch which one blows up.</source>
        <translation>Euler, punto medio y RK4 desde el mismo inicio con DT = %1 s (tesis 7.2.2, figs. 41-43). Observe cuál explota.</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>ilimitado</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>Cheapest and least stable: on an undamped spring it gains energy at every DT. On the two-layer ring it holds for 2 s up to DT %1 s (measured).</source>
        <translation>El más barato y el menos estable: en un resorte sin amortiguar gana energía con cada DT. En el anillo de dos capas aguanta 2 s hasta DT %1 s (medido).</translation>
    </message>
    <message>
        <source>Two force evaluations per step, second order; on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03.</source>
        <translation>Dos evaluaciones de fuerza por paso, segundo orden; en el anillo de dos capas aguanta 2 s hasta DT %1 s (medido), así que falla con el 0,03 de la tesis.</translation>
    </message>
    <message>
        <source>Four evaluations, fourth order; stable up to h·ω ≈ 2.8: on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03 and 0.3.</source>
        <translation>Cuatro evaluaciones, cuarto orden; estable hasta h·ω ≈ 2,8: en el anillo de dos capas aguanta 2 s hasta DT %1 s (medido), así que falla con los 0,03 y 0,3 de la tesis.</translation>
    </message>
    <message>
        <source>Same cost as Euler, but energy stays bounded on an undamped spring (h·ω &amp;lt; 2).</source>
        <translation>El mismo coste que Euler, pero la energía se mantiene acotada en un resorte sin amortiguar (h·ω &amp;lt; 2).</translation>
    </message>
    <message>
        <source>Velocity Verlet: time-reversible, good long-run energy behaviour. Second order without damping; with the dampers on (every scene here) its damping sees the half-step velocity and it is first order: the fitted order on the damped spring is %1 (measured).</source>
        <translation>Verlet de velocidades: reversible en el tiempo, buen comportamiento de la energía a largo plazo. Segundo orden sin amortiguamiento; con los amortiguadores activos (en todas las escenas aquí) su amortiguamiento ve la velocidad del medio paso y es de primer orden: el orden ajustado en el resorte amortiguado es %1 (medido).</translation>
    </message>
    <message>
        <source>2 (1 damped)</source>
        <translation>2 (1 amortiguado)</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Lessons&lt;/b&gt; menu (or Help → Experiments): %1 guided experiments, each set up in one click, with what to change, what to look at and the answer measured with elastic-lab-cli; the Lesson dock shows what each answer expects beside what your run gives.&lt;/p&gt;</source>
        <translation>&lt;p&gt;Menú &lt;b&gt;Lecciones&lt;/b&gt; (o Ayuda → Experimentos): %1 experimentos guiados, cada uno preparado con un clic, con qué cambiar, qué observar y la respuesta medida con elastic-lab-cli; el panel Lección muestra lo que espera cada respuesta junto a lo que da su ejecución.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>Lessons &gt; Lesson texts explains what to do.</source>
        <translation>Lecciones &gt; Textos de las lecciones explica qué hacer.</translation>
    </message>
    <message>
        <source>height of particle %1</source>
        <translation>altura de la partícula %1</translation>
    </message>
    <message>
        <source>speed of particle %1</source>
        <translation>velocidad de la partícula %1</translation>
    </message>
    <message>
        <source>height of the inner layer&apos;s centre</source>
        <translation>altura del centro de la capa interior</translation>
    </message>
    <message>
        <source>height of the outer layer&apos;s centre</source>
        <translation>altura del centro de la capa exterior</translation>
    </message>
    <message>
        <source>centre-of-mass height</source>
        <translation>altura del centro de masas</translation>
    </message>
    <message>
        <source>centre-of-mass speed</source>
        <translation>velocidad del centro de masas</translation>
    </message>
    <message>
        <source>layers&apos; separation</source>
        <translation>separación de las capas</translation>
    </message>
    <message>
        <source>9. Two balloons collide: momentum and energy</source>
        <translation>9. Dos globos chocan: cantidad de movimiento y energía</translation>
    </message>
    <message>
        <source>10. A soft stack: how the bottom body carries the others</source>
        <translation>10. Una pila blanda: cómo el cuerpo de abajo sostiene a los demás</translation>
    </message>
</context>
<context>
    <name>WorldExport</name>
    <message>
        <source>No run of several bodies to export</source>
        <translation>No hay ninguna simulación de varios cuerpos que exportar</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Exportar datos</translation>
    </message>
    <message>
        <source>CSV of several bodies, comma and decimal point (*.csv)</source>
        <translation>CSV de varios cuerpos, coma y punto decimal (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %1 rows of the world to %2</source>
        <translation>Se escribieron %1 filas del mundo en %2</translation>
    </message>
</context>
<context>
    <name>elui::BodiesDock</name>
    <message>
        <source>Bodies</source>
        <translation>Cuerpos</translation>
    </message>
    <message>
        <source>The bodies of the scene, total momentum and the smallest gap, with their curves against simulated time</source>
        <translation>Los cuerpos de la escena, la cantidad de movimiento total y la menor separación, con sus curvas frente al tiempo simulado</translation>
    </message>
    <message>
        <source>This dock is for scenes of several bodies: Presets &gt; Several bodies, or a scene file of several bodies.</source>
        <translation>Este panel es para escenas de varios cuerpos: Ajustes predefinidos &gt; Varios cuerpos, o un archivo de escena de varios cuerpos.</translation>
    </message>
    <message>
        <source>body</source>
        <translation>cuerpo</translation>
    </message>
    <message>
        <source>mass [kg]</source>
        <translation>masa [kg]</translation>
    </message>
    <message>
        <source>centre [m]</source>
        <translation>centro [m]</translation>
    </message>
    <message>
        <source>velocity [m/s]</source>
        <translation>velocidad [m/s]</translation>
    </message>
    <message>
        <source>volume in/out</source>
        <translation>volumen int./ext.</translation>
    </message>
    <message>
        <source>pressure in/out</source>
        <translation>presión int./ext.</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>Cantidad de movimiento total</translation>
    </message>
    <message>
        <source>min_gap</source>
        <translation>min_gap</translation>
    </message>
    <message>
        <source>Volume per body and layer</source>
        <translation>Volumen por cuerpo y capa</translation>
    </message>
    <message>
        <source>Pressure per body and layer</source>
        <translation>Presión por cuerpo y capa</translation>
    </message>
    <message>
        <source>gap [m]</source>
        <translation>separación [m]</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>volumen</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>presión</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>ring2d: particles per layer; sphere3d: subdivisions; sphere3d-latlong: slices</source>
        <translation>ring2d: partículas por capa; sphere3d: subdivisiones; sphere3d-latlong: rebanadas</translation>
    </message>
    <message>
        <source>kind, level</source>
        <translation>tipo, nivel</translation>
    </message>
    <message>
        <source>where [m]</source>
        <translation>dónde [m]</translation>
    </message>
    <message>
        <source>how fast [m/s]</source>
        <translation>qué tan rápido [m/s]</translation>
    </message>
    <message>
        <source>Add body</source>
        <translation>Añadir cuerpo</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>Quitar el seleccionado</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>interior</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>exterior</translation>
    </message>
    <message>
        <source> (body%1 with itself)</source>
        <translation> (body%1 consigo mismo)</translation>
    </message>
    <message>
        <source> (body%1 and body%2)</source>
        <translation> (body%1 y body%2)</translation>
    </message>
    <message>
        <source>beyond %1 m (nothing that close)</source>
        <translation>más de %1 m (nada tan cerca)</translation>
    </message>
    <message>
        <source>&lt;b&gt;momentum&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;angular momentum&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contact between bodies&lt;/b&gt; %4 J, %5 pairs in the skin</source>
        <translation>&lt;b&gt;cantidad de movimiento&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;momento angular&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contacto entre cuerpos&lt;/b&gt; %4 J, %5 pares en la piel</translation>
    </message>
    <message>
        <source>%1: not a number</source>
        <translation>%1: no es un número</translation>
    </message>
    <message>
        <source>Choose a body in the list first.</source>
        <translation>Elija primero un cuerpo de la lista.</translation>
    </message>
    <message>
        <source>A world keeps at least one body.</source>
        <translation>Un mundo conserva al menos un cuerpo.</translation>
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
        <translation>Lado a lado</translation>
    </message>
    <message>
        <source>Run the same scene with up to three integrators from the same start state. Parameter edits and mouse drags go to all of them.</source>
        <translation>Ejecutar la misma escena con hasta tres integradores desde el mismo estado inicial. Los cambios de parámetros y los arrastres con el ratón van a todos.</translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(ninguno)</translation>
    </message>
    <message>
        <source>View %1</source>
        <translation>Vista %1</translation>
    </message>
    <message>
        <source>The integrator of the first view</source>
        <translation>El integrador de la primera vista</translation>
    </message>
    <message>
        <source>The integrator of this view, or none</source>
        <translation>El integrador de esta vista, o ninguno</translation>
    </message>
    <message>
        <source>%1 s, common to every view (set it in the Run dock)</source>
        <translation>%1 s, común a todas las vistas (se ajusta en el panel Ejecución)</translation>
    </message>
    <message>
        <source>DT</source>
        <translation>DT</translation>
    </message>
    <message>
        <source>Start the views side by side from the current start state</source>
        <translation>Iniciar las vistas lado a lado desde el estado inicial actual</translation>
    </message>
    <message>
        <source>Keep the views as they are</source>
        <translation>Dejar las vistas como están</translation>
    </message>
</context>
<context>
    <name>elui::ConservationDialog</name>
    <message>
        <source>Long-time energy</source>
        <translation>Energía a largo plazo</translation>
    </message>
    <message>
        <source>Run length in periods of the body&apos;s fastest mode (damping switched off)</source>
        <translation>Duración en periodos del modo más rápido del cuerpo (amortiguamiento desactivado)</translation>
    </message>
    <message>
        <source>The fixed step of every run [s]</source>
        <translation>El paso fijo de cada ejecución [s]</translation>
    </message>
    <message>
        <source>float: the float build of the 1D spring, where round-off shows as a random walk</source>
        <translation>float: la versión float del resorte 1D, donde el redondeo aparece como un paseo aleatorio</translation>
    </message>
    <message>
        <source>Periods</source>
        <translation>Periodos</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Precisión</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|energy error| envelope [J]</source>
        <translation>envolvente de |error de energía| [J]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>α</source>
        <translation>α</translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation>intervalo del 95 %</translation>
    </message>
    <message>
        <source>class</source>
        <translation>clase</translation>
    </message>
    <message>
        <source>final |ΔE| [J]</source>
        <translation>|ΔE| final [J]</translation>
    </message>
    <message>
        <source>relative</source>
        <translation>relativo</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>%1: %2, α = %3</source>
        <translation>%1: %2, α = %3</translation>
    </message>
    <message>
        <source>%1: failed</source>
        <translation>%1: falló</translation>
    </message>
    <message>
        <source>slope 1/2 (random walk)</source>
        <translation>pendiente 1/2 (paseo aleatorio)</translation>
    </message>
    <message>
        <source>slope 1 (drift)</source>
        <translation>pendiente 1 (deriva)</translation>
    </message>
    <message>
        <source>The study did not run: %1</source>
        <translation>El estudio no se ejecutó: %1</translation>
    </message>
    <message>
        <source>Undamped (%1). Fastest mode ω = %2 rad/s, period %3 s; DT = %4 s (h·ω = %5); %6 periods = %7 s. α: slope of log |ΔE| against log t from 10 periods on; bounded &lt; 0.25 ≤ random walk &lt; 0.75 ≤ drift.</source>
        <translation>Sin amortiguar (%1). Modo más rápido ω = %2 rad/s, periodo %3 s; DT = %4 s (h·ω = %5); %6 periodos = %7 s. α: pendiente de log |ΔE| frente a log t a partir de 10 periodos; acotado &lt; 0,25 ≤ paseo aleatorio &lt; 0,75 ≤ deriva.</translation>
    </message>
</context>
<context>
    <name>elui::EnergyBarsDock</name>
    <message>
        <source>Energy bars</source>
        <translation>Barras de energía</translation>
    </message>
    <message>
        <source>Each part of the energy as a bar, named on the axis; the values are in the Run dock&apos;s readout</source>
        <translation>Cada parte de la energía como una barra, nombrada en el eje; los valores están en la lectura del panel Ejecución</translation>
    </message>
    <message>
        <source>Energy book</source>
        <translation>Balance de energía</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>energía [J]</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
total %2, at the start %3</source>
        <translation>Energía en t = %1 s
total %2, al inicio %3</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
%2</source>
        <translation>Energía en t = %1 s
%2</translation>
    </message>
</context>
<context>
    <name>elui::FailureBanner</name>
    <message>
        <source>Start again from the beginning with the step that ran through the failed stretch</source>
        <translation>Empezar de nuevo desde el principio con el paso que atravesó el tramo fallido</translation>
    </message>
    <message>
        <source>Use implicit-euler and reset</source>
        <translation>Usar implicit-euler y reiniciar</translation>
    </message>
    <message>
        <source>Start again with the implicit Euler integrator, which is stable at any time step</source>
        <translation>Empezar de nuevo con el integrador de Euler implícito, estable con cualquier paso de tiempo</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Start again from the beginning with the same settings</source>
        <translation>Empezar de nuevo desde el principio con los mismos ajustes</translation>
    </message>
    <message>
        <source>&lt;b&gt;The simulation blew up&lt;/b&gt; at t = %1 s (step %2): %3. The run is paused and shows the last good state.</source>
        <translation>&lt;b&gt;La simulación explotó&lt;/b&gt; en t = %1 s (paso %2): %3. La ejecución está en pausa y muestra el último estado válido.</translation>
    </message>
    <message>
        <source>Checking whether a smaller step survives the same stretch (a re-run at a quarter of DT, in the background)…</source>
        <translation>Comprobando si un paso menor sobrevive al mismo tramo (una nueva ejecución con un cuarto de DT, en segundo plano)…</translation>
    </message>
    <message>
        <source>Try a smaller DT, a more stable integrator (rk4, or implicit-euler), softer springs or less pressure, then Reset.</source>
        <translation>Pruebe un DT menor, un integrador más estable (rk4 o implicit-euler), resortes más blandos o menos presión, y luego Reiniciar.</translation>
    </message>
    <message>
        <source>Use DT = %1 s and reset</source>
        <translation>Usar DT = %1 s y reiniciar</translation>
    </message>
    <message>
        <source>The body itself collapses — no step size will save it: run again from t = %1 s at a step of %2 s (%3), it fails at t = %4 s as well (%5). Change the body instead: lighter masses or less gravity, stiffer springs (ks, and the radial ones), more gas pressure, or more damping.</source>
        <translation>El propio cuerpo colapsa — ningún tamaño de paso lo salvará: ejecutado de nuevo desde t = %1 s con un paso de %2 s (%3), también falla en t = %4 s (%5). Cambie en su lugar el cuerpo: masas más ligeras o menos gravedad, resortes más rígidos (ks, y los radiales), más presión del gas o más amortiguamiento.</translation>
    </message>
    <message>
        <source>The step was too large: run again from t = %1 s at a step of %2 s, the same stretch runs through t = %3 s. The linearised body agrees: %4.</source>
        <translation>El paso era demasiado grande: ejecutado de nuevo desde t = %1 s con un paso de %2 s, el mismo tramo llega hasta t = %3 s. El cuerpo linealizado lo confirma: %4.</translation>
    </message>
</context>
<context>
    <name>elui::HelpDialog</name>
    <message>
        <source>Elastic Lab help</source>
        <translation>Ayuda de Elastic Lab</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>Ayuda</translation>
    </message>
    <message>
        <source>How to use Elastic Lab: the view, the docks, the integrators and the files</source>
        <translation>Cómo usar Elastic Lab: la vista, los paneles, los integradores y los archivos</translation>
    </message>
    <message>
        <source>Close the help</source>
        <translation>Cerrar la ayuda</translation>
    </message>
</context>
<context>
    <name>elui::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>Lección</translation>
    </message>
    <message>
        <source>Run until t =</source>
        <translation>Ejecutar hasta t =</translation>
    </message>
    <message>
        <source>Run as fast as possible and pause at this simulated time.</source>
        <translation>Ejecutar lo más rápido posible y pausar en este tiempo simulado.</translation>
    </message>
    <message>
        <source>Simulated time between Start and Stop (the first view&apos;s clock).</source>
        <translation>Tiempo simulado entre Inicio y Parar (el reloj de la primera vista).</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>Inicio</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>Cero</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>respuesta</translation>
    </message>
    <message>
        <source>expected</source>
        <translation>esperado</translation>
    </message>
    <message>
        <source>you got</source>
        <translation>obtenido</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>Medir</translation>
    </message>
    <message>
        <source>Measure every answer on the parameters in use, as the lesson&apos;s elastic-lab-cli commands do (stability scans, weightless impacts, runs).</source>
        <translation>Medir cada respuesta con los parámetros en uso, como hacen los comandos elastic-lab-cli de la lección (barridos de estabilidad, choques sin gravedad, ejecuciones).</translation>
    </message>
    <message>
        <source>&lt;small&gt;you got: from your run, or &lt;i&gt;measured&lt;/i&gt; (Measure); green within the text&apos;s tolerance, amber off it&lt;/small&gt;</source>
        <translation>&lt;small&gt;obtenido: de su ejecución, o &lt;i&gt;medido&lt;/i&gt; (Medir); verde dentro de la tolerancia del texto, ámbar fuera de ella&lt;/small&gt;</translation>
    </message>
    <message>
        <source>No lesson: choose one in the Lessons menu. Run until and the stopwatch work for any scene.</source>
        <translation>Ninguna lección: elija una en el menú Lecciones. «Ejecutar hasta» y el cronómetro funcionan en cualquier escena.</translation>
    </message>
    <message>
        <source>Stopwatch: &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>Cronómetro: &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>Parar</translation>
    </message>
    <message>
        <source>read off your run</source>
        <translation>leído de su ejecución</translation>
    </message>
    <message>
        <source>press Measure</source>
        <translation>pulse Medir</translation>
    </message>
    <message>
        <source>measured on the parameters in use</source>
        <translation>medido con los parámetros en uso</translation>
    </message>
    <message>
        <source>t = &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation>t = &lt;b&gt;%1 s&lt;/b&gt;</translation>
    </message>
    <message>
        <source>%1: energy drift &lt;b&gt;%2 J&lt;/b&gt;%3</source>
        <translation>%1: deriva de energía &lt;b&gt;%2 J&lt;/b&gt;%3</translation>
    </message>
    <message>
        <source>, blew up at t = %1 s</source>
        <translation>, explotó en t = %1 s</translation>
    </message>
    <message>
        <source>centre of mass: %1 m above the floor, vertical speed %2 m/s</source>
        <translation>centro de masas: %1 m sobre el suelo, velocidad vertical %2 m/s</translation>
    </message>
    <message>
        <source>layer centres above the floor: inner %1 m, outer %2 m; the inner one sits &lt;b&gt;%3 m&lt;/b&gt; %4</source>
        <translation>centros de las capas sobre el suelo: interior %1 m, exterior %2 m; la interior está &lt;b&gt;%3 m&lt;/b&gt; %4</translation>
    </message>
    <message>
        <source>below</source>
        <translation>por debajo</translation>
    </message>
    <message>
        <source>above</source>
        <translation>por encima</translation>
    </message>
    <message>
        <source>centre of mass hit the floor at %1 m/s%2</source>
        <translation>el centro de masas chocó con el suelo a %1 m/s%2</translation>
    </message>
    <message>
        <source>, left it at %1 m/s (ratio %2)</source>
        <translation>, lo dejó a %1 m/s (razón %2)</translation>
    </message>
    <message>
        <source>lowest point %1 m above the floor%2</source>
        <translation>punto más bajo %1 m sobre el suelo%2</translation>
    </message>
    <message>
        <source>lowest point %1 m into the floor (contact)%2</source>
        <translation>punto más bajo %1 m dentro del suelo (contacto)%2</translation>
    </message>
    <message>
        <source>; last left the floor at t = %1 s</source>
        <translation>; dejó el suelo por última vez en t = %1 s</translation>
    </message>
    <message>
        <source>inner layer: %1 %2, pressure %3 %4</source>
        <translation>capa interior: %1 %2, presión %3 %4</translation>
    </message>
    <message>
        <source>measuring on the parameters in use…</source>
        <translation>midiendo con los parámetros en uso…</translation>
    </message>
    <message>
        <source>Run until a time, a stopwatch, and each answer of the lesson beside what your run gives</source>
        <translation>Ejecutar hasta un instante, un cronómetro, y cada respuesta de la lección junto a lo que da su ejecución</translation>
    </message>
    <message>
        <source>Run until this simulated time</source>
        <translation>Ejecutar hasta este tiempo simulado</translation>
    </message>
    <message>
        <source>The simulated time [s] at which Run until pauses</source>
        <translation>El tiempo simulado [s] en el que «Ejecutar hasta» se detiene</translation>
    </message>
    <message>
        <source>Start or stop the stopwatch on the simulated clock</source>
        <translation>Iniciar o parar el cronómetro sobre el reloj simulado</translation>
    </message>
    <message>
        <source>Set the stopwatch back to zero</source>
        <translation>Poner el cronómetro a cero</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; smallest gap %2 m</source>
        <translation>cantidad de movimiento total &lt;b&gt;%1 kg m/s&lt;/b&gt;; menor separación %2 m</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; no gap below %2 m</source>
        <translation>cantidad de movimiento total &lt;b&gt;%1 kg m/s&lt;/b&gt;; ninguna separación por debajo de %2 m</translation>
    </message>
    <message>
        <source>body%1: centre velocity %2 m/s, outer %3 %4 of %5 at rest</source>
        <translation>body%1: velocidad del centro %2 m/s, %3 exterior %4 de %5 en reposo</translation>
    </message>
    <message>
        <source>area</source>
        <translation>área</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>volumen</translation>
    </message>
</context>
<context>
    <name>elui::LessonsDialog</name>
    <message>
        <source>Experiments</source>
        <translation>Experimentos</translation>
    </message>
    <message>
        <source>Short guided experiments: each sets up a scene, says what to change and what to look at, and gives the answer measured with elastic-lab-cli.</source>
        <translation>Experimentos guiados breves: cada uno prepara una escena, dice qué cambiar y qué observar, y da la respuesta medida con elastic-lab-cli.</translation>
    </message>
    <message>
        <source>The guided experiments; the arrow keys choose one, its text is beside the list</source>
        <translation>Los experimentos guiados; las flechas eligen uno, su texto está junto a la lista</translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>Experimento</translation>
    </message>
    <message>
        <source>What the chosen experiment sets up, what to change and what to look for</source>
        <translation>Qué prepara el experimento elegido, qué cambiar y qué observar</translation>
    </message>
    <message>
        <source>Set up this experiment</source>
        <translation>Preparar este experimento</translation>
    </message>
    <message>
        <source>Set up the chosen experiment in the main window: its scene, parameters and docks</source>
        <translation>Preparar el experimento elegido en la ventana principal: su escena, parámetros y paneles</translation>
    </message>
    <message>
        <source>Close the experiments; the main window keeps its scene</source>
        <translation>Cerrar los experimentos; la ventana principal conserva su escena</translation>
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
        <translation>&amp;Abrir escena...</translation>
    </message>
    <message>
        <source>A scene file (.json): scene, parameters, integrator and, if saved, the exact state</source>
        <translation>Un archivo de escena (.json): escena, parámetros, integrador y, si se guardó, el estado exacto</translation>
    </message>
    <message>
        <source>&amp;Save scene</source>
        <translation>&amp;Guardar escena</translation>
    </message>
    <message>
        <source>Scene, every parameter, the integrator and the exact current state</source>
        <translation>La escena, todos los parámetros, el integrador y el estado actual exacto</translation>
    </message>
    <message>
        <source>Save scene &amp;as...</source>
        <translation>Guardar escena &amp;como...</translation>
    </message>
    <message>
        <source>Export &amp;Data (CSV, Excel)...</source>
        <translation>Exportar &amp;datos (CSV, Excel)...</translation>
    </message>
    <message>
        <source>The time series of this run, with the same columns as elastic-lab-cli run --csv</source>
        <translation>La serie temporal de esta ejecución, con las mismas columnas que elastic-lab-cli run --csv</translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG, PDF)...</source>
        <translation>Exportar &amp;gráficos (PNG, SVG, PDF)...</translation>
    </message>
    <message>
        <source>Save &amp;viewport screenshot...</source>
        <translation>Guardar &amp;captura de la vista...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;Salir</translation>
    </message>
    <message>
        <source>&amp;Run / Pause</source>
        <translation>&amp;Ejecutar / Pausa</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;Paso</translation>
    </message>
    <message>
        <source>R&amp;eset</source>
        <translation>&amp;Reiniciar</translation>
    </message>
    <message>
        <source>Reset &amp;view</source>
        <translation>Restablecer &amp;vista</translation>
    </message>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>Modo &amp;presentación</translation>
    </message>
    <message>
        <source>Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector</source>
        <translation>Todo %1 veces más grande, con botones grandes de Ejecutar, Paso, Atrás y Reiniciar: para un proyector</translation>
    </message>
    <message>
        <source>&amp;Larger text</source>
        <translation>Texto más &amp;grande</translation>
    </message>
    <message>
        <source>S&amp;maller text</source>
        <translation>Texto más &amp;pequeño</translation>
    </message>
    <message>
        <source>Structural springs</source>
        <translation>Resortes estructurales</translation>
    </message>
    <message>
        <source>Radius springs</source>
        <translation>Resortes radiales</translation>
    </message>
    <message>
        <source>Shear springs</source>
        <translation>Resortes de cizalla</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>Caras</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>Partículas</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>Normales</translation>
    </message>
    <message>
        <source>Force vectors</source>
        <translation>Vectores de fuerza</translation>
    </message>
    <message>
        <source>Colour springs by strain</source>
        <translation>Colorear resortes según la deformación</translation>
    </message>
    <message>
        <source>Collision box</source>
        <translation>Caja de colisión</translation>
    </message>
    <message>
        <source>&amp;Side by side...</source>
        <translation>&amp;Lado a lado...</translation>
    </message>
    <message>
        <source>Single &amp;view</source>
        <translation>&amp;Vista única</translation>
    </message>
    <message>
        <source>Elastic Lab &amp;help</source>
        <translation>A&amp;yuda de Elastic Lab</translation>
    </message>
    <message>
        <source>Guided experiments: a scene set up in one click, what to change, what to look at, the measured answer</source>
        <translation>Experimentos guiados: una escena preparada con un clic, qué cambiar, qué observar, la respuesta medida</translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;Acerca de</translation>
    </message>
    <message>
        <source>About Elastic Lab</source>
        <translation>Acerca de Elastic Lab</translation>
    </message>
    <message>
        <source>Elastic Lab: the dynamics of two-layer elastic bodies, for teaching.</source>
        <translation>Elastic Lab: la dinámica de cuerpos elásticos de dos capas, para la enseñanza.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;Archivo</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>Abrir &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;Simulación</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;Ver</translation>
    </message>
    <message>
        <source>&amp;High contrast</source>
        <translation>&amp;Alto contraste</translation>
    </message>
    <message>
        <source>White text on black, yellow highlight and focus: for low vision and projectors</source>
        <translation>Texto blanco sobre negro, resaltado y foco amarillos: para baja visión y proyectores</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;Comparar</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>&amp;Ajustes predefinidos</translation>
    </message>
    <message>
        <source>S&amp;tudies</source>
        <translation>Es&amp;tudios</translation>
    </message>
    <message>
        <source>&amp;Work-precision study...</source>
        <translation>Estudio &amp;trabajo-precisión...</translation>
    </message>
    <message>
        <source>&amp;Refinement study...</source>
        <translation>Estudio de &amp;refinamiento...</translation>
    </message>
    <message>
        <source>&amp;Stability scan...</source>
        <translation>Barrido de &amp;estabilidad...</translation>
    </message>
    <message>
        <source>&amp;Long-time energy...</source>
        <translation>Energía a &amp;largo plazo...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>A&amp;yuda</translation>
    </message>
    <message>
        <source>DT set to %1 s</source>
        <translation>DT fijado en %1 s</translation>
    </message>
    <message>
        <source>Use implicit-euler</source>
        <translation>Usar implicit-euler</translation>
    </message>
    <message>
        <source>Linearised backward Euler: stable at any DT (and damps more)</source>
        <translation>Euler implícito linealizado: estable con cualquier DT (y amortigua más)</translation>
    </message>
    <message>
        <source>Keep DT</source>
        <translation>Mantener DT</translation>
    </message>
    <message>
        <source>Run with this DT anyway (to watch the method fail, for example)</source>
        <translation>Ejecutar con este DT de todos modos (por ejemplo, para ver fallar el método)</translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3, which this display does not offer.
Plots, parameters and exports still work.</source>
        <translation>La vista 3D necesita OpenGL 3.3, que esta pantalla no ofrece.
Los gráficos, los parámetros y las exportaciones siguen funcionando.</translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>Abrir escena</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>No se pudo abrir %1: %2</translation>
    </message>
    <message>
        <source>Cannot build that body: %1</source>
        <translation>No se puede construir ese cuerpo: %1</translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>&amp;Idioma</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>Idioma del sistema</translation>
    </message>
    <message>
        <source>Applies at the next start (now: %1)</source>
        <translation>Se aplica en el próximo inicio (ahora: %1)</translation>
    </message>
    <message>
        <source>The language changes when Elastic Lab starts again.</source>
        <translation>El idioma cambia cuando Elastic Lab se vuelve a iniciar.</translation>
    </message>
    <message>
        <source>Language: %1 at the next start</source>
        <translation>Idioma: %1 en el próximo inicio</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>Idioma</translation>
    </message>
    <message>
        <source>Class controls</source>
        <translation>Controles de clase</translation>
    </message>
    <message>
        <source>Presentation mode: text %1x (Ctrl+= larger, Ctrl+- smaller, F5 off)</source>
        <translation>Modo presentación: texto %1x (Ctrl+= más grande, Ctrl+- más pequeño, F5 desactiva)</translation>
    </message>
    <message>
        <source>Normal text size</source>
        <translation>Tamaño de texto normal</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>Cambios sin guardar</translation>
    </message>
    <message>
        <source>The parameters or the integrator of %1 have changed since it was saved.</source>
        <translation>Los parámetros o el integrador de %1 han cambiado desde que se guardó.</translation>
    </message>
    <message>
        <source>Save stores the changes and the current state in the file.</source>
        <translation>Guardar almacena los cambios y el estado actual en el archivo.</translation>
    </message>
    <message>
        <source> Press Run (Space).</source>
        <translation> Pulse Ejecutar (Espacio).</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>&amp;Pausa</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;Ejecutar</translation>
    </message>
    <message>
        <source>&lt;b&gt;This body is likely unstable at the current DT.&lt;/b&gt; %1. The run is paused.</source>
        <translation>&lt;b&gt;Este cuerpo probablemente es inestable con el DT actual.&lt;/b&gt; %1. La ejecución está en pausa.</translation>
    </message>
    <message>
        <source>Use DT = %1 s</source>
        <translation>Usar DT = %1 s</translation>
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
        <translation>(ninguno)</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>&amp;Vaciar</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json);;All files (*)</source>
        <translation>Escenas de Elastic Lab (*.json);;Todos los archivos (*)</translation>
    </message>
    <message>
        <source>Could not open %1: not a regular file</source>
        <translation>No se pudo abrir %1: no es un archivo normal</translation>
    </message>
    <message>
        <source>Could not open %1: no such file</source>
        <translation>No se pudo abrir %1: el archivo no existe</translation>
    </message>
    <message>
        <source>Could not open %1: %2 bytes is too large for a scene file</source>
        <translation>No se pudo abrir %1: %2 bytes es demasiado para un archivo de escena</translation>
    </message>
    <message>
        <source>%1 is not a scene this program can open:
%2</source>
        <translation>%1 no es una escena que este programa pueda abrir:
%2</translation>
    </message>
    <message>
        <source>Opened %1: the saved state at t = %2 s, paused. Press Run (Space).</source>
        <translation>Abierto %1: el estado guardado en t = %2 s, en pausa. Pulse Ejecutar (Espacio).</translation>
    </message>
    <message>
        <source>Opened %1 (no saved state: starts at t = 0). Press Run (Space).</source>
        <translation>Abierto %1 (sin estado guardado: empieza en t = 0). Pulse Ejecutar (Espacio).</translation>
    </message>
    <message>
        <source>%1 no longer exists; it has been removed from the recent files.</source>
        <translation>%1 ya no existe; se ha quitado de los archivos recientes.</translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>Abrir reciente</translation>
    </message>
    <message>
        <source>Save scene as</source>
        <translation>Guardar escena como</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json)</source>
        <translation>Escenas de Elastic Lab (*.json)</translation>
    </message>
    <message>
        <source>Could not save %1: no scene is running yet</source>
        <translation>No se pudo guardar %1: todavía no hay ninguna escena en marcha</translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>Guardar escena</translation>
    </message>
    <message>
        <source>Saved the first view (%1) at t = %2 s to %3; %4 not in the file.</source>
        <translation>Se guardó la primera vista (%1) en t = %2 s en %3; %4 en el archivo.</translation>
    </message>
    <message>
        <source>the second view is</source>
        <translation>la segunda vista no está</translation>
    </message>
    <message>
        <source>the other views are</source>
        <translation>las otras vistas no están</translation>
    </message>
    <message>
        <source>Saved %1 at t = %2 s (%3).</source>
        <translation>Se guardó %1 en t = %2 s (%3).</translation>
    </message>
    <message>
        <source>CSV, comma and decimal point (*.csv)</source>
        <translation>CSV, coma y punto decimal (*.csv)</translation>
    </message>
    <message>
        <source>CSV for spreadsheets, semicolon and decimal comma (*.csv)</source>
        <translation>CSV para hojas de cálculo, punto y coma y coma decimal (*.csv)</translation>
    </message>
    <message>
        <source>Excel workbook with charts (*.xlsx)</source>
        <translation>Libro de Excel con gráficos (*.xlsx)</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>Exportar datos</translation>
    </message>
    <message>
        <source>Wrote %1 rows to %2</source>
        <translation>Se escribieron %1 filas en %2</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>Exportar gráficos</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation>Imagen PNG (*.png);;Dibujo SVG (*.svg);;Documento PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Se escribió %1</translation>
    </message>
    <message>
        <source>Save viewport screenshot</source>
        <translation>Guardar captura de la vista</translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation>Imagen PNG (*.png)</translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>Guardar captura</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>Paso &amp;atrás</translation>
    </message>
    <message>
        <source>Timeline s&amp;tart</source>
        <translation>&amp;Inicio de la línea de tiempo</translation>
    </message>
    <message>
        <source>Timeline &amp;newest</source>
        <translation>Momento más &amp;reciente</translation>
    </message>
    <message>
        <source>&amp;Clear abandoned future</source>
        <translation>&amp;Borrar el futuro abandonado</translation>
    </message>
    <message>
        <source>Velocity vectors</source>
        <translation>Vectores de velocidad</translation>
    </message>
    <message>
        <source>Ruler (drag to measure)</source>
        <translation>Regla (arrastre para medir)</translation>
    </message>
    <message>
        <source>Lesson &amp;texts (Experiments)...</source>
        <translation>&amp;Textos de las lecciones (Experimentos)...</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>&amp;Lecciones</translation>
    </message>
    <message>
        <source>%1: set up. Lessons &gt; Lesson texts says what to change and what to look at. Press Run (Space).</source>
        <translation>%1: preparado. Lecciones &gt; Textos de las lecciones dice qué cambiar y qué observar. Pulse Ejecutar (Espacio).</translation>
    </message>
    <message>
        <source>Plotting the %1 against time (the Measured dock).</source>
        <translation>Dibujando frente al tiempo: %1 (el panel Medido).</translation>
    </message>
    <message>
        <source>Particle %1</source>
        <translation>Partícula %1</translation>
    </message>
    <message>
        <source>Plot its height</source>
        <translation>Dibujar su altura</translation>
    </message>
    <message>
        <source>Plot its speed</source>
        <translation>Dibujar su velocidad</translation>
    </message>
    <message>
        <source>Plot the inner layer&apos;s centre height</source>
        <translation>Dibujar la altura del centro de la capa interior</translation>
    </message>
    <message>
        <source>Plot the outer layer&apos;s centre height</source>
        <translation>Dibujar la altura del centro de la capa exterior</translation>
    </message>
    <message>
        <source>Body</source>
        <translation>Cuerpo</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass height</source>
        <translation>Dibujar la altura del centro de masas</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass speed</source>
        <translation>Dibujar la velocidad del centro de masas</translation>
    </message>
    <message>
        <source>Plot the layers&apos; separation</source>
        <translation>Dibujar la separación de las capas</translation>
    </message>
    <message>
        <source>Several &amp;bodies</source>
        <translation>Varios &amp;cuerpos</translation>
    </message>
    <message>
        <source>%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body selector. Press Run (Space).</source>
        <translation>%1: varios cuerpos. El panel Cuerpos muestra la cantidad de movimiento y min_gap; Parámetros tiene un selector de cuerpo. Pulse Ejecutar (Espacio).</translation>
    </message>
    <message>
        <source>Long-time energy</source>
        <translation>Energía a largo plazo</translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation>Lado a lado</translation>
    </message>
</context>
<context>
    <name>elui::MeasurePlotDock</name>
    <message>
        <source>Measured</source>
        <translation>Medido</translation>
    </message>
    <message>
        <source>Right-click a particle or the body in the view to plot it here.</source>
        <translation>Haga clic derecho en una partícula o en el cuerpo en la vista para dibujarlo aquí.</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>Quitar todo</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>length [m]</source>
        <translation>longitud [m]</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>velocidad [m/s]</translation>
    </message>
</context>
<context>
    <name>elui::Pacer</name>
    <message>
        <source>Real time</source>
        <translation>Tiempo real</translation>
    </message>
    <message>
        <source>1/4 speed</source>
        <translation>Velocidad 1/4</translation>
    </message>
    <message>
        <source>1/10 speed</source>
        <translation>Velocidad 1/10</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>Lo más rápido posible</translation>
    </message>
</context>
<context>
    <name>elui::ParameterDock</name>
    <message>
        <source>Parameters</source>
        <translation>Parámetros</translation>
    </message>
    <message>
        <source>Every parameter of the scene with its unit; a change applies at once</source>
        <translation>Todos los parámetros de la escena con su unidad; un cambio se aplica al instante</translation>
    </message>
    <message>
        <source>Reset all to the scene&apos;s defaults</source>
        <translation>Todo a valores por defecto</translation>
    </message>
    <message>
        <source>Every parameter here (and DT) back to the scene&apos;s default; the body&apos;s shape stays (Scene dock).</source>
        <translation>Cada parámetro de aquí (y DT) vuelve al valor por defecto de la escena; la forma del cuerpo se mantiene (panel Escena).</translation>
    </message>
    <message>
        <source>The body whose parameters are shown and edited; world parameters (gravity, box, contact, dt) are every body&apos;s.</source>
        <translation>El cuerpo cuyos parámetros se muestran y editan; los parámetros del mundo (gravedad, caja, contacto, dt) son de todos los cuerpos.</translation>
    </message>
    <message>
        <source>body%1 (%2)</source>
        <translation>body%1 (%2)</translation>
    </message>
    <message>
        <source>every body</source>
        <translation>todos los cuerpos</translation>
    </message>
</context>
<context>
    <name>elui::ParameterForm</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;default: %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;por defecto: %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;allowed: %4&lt;br&gt;default: %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;permitido: %4&lt;br&gt;por defecto: %5</translation>
    </message>
    <message>
        <source>Set DT in the Run dock.</source>
        <translation>Ajuste DT en el panel Ejecución.</translation>
    </message>
    <message>
        <source>key: %1</source>
        <translation>clave: %1</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number; allowed %3</source>
        <translation>%1: «%2» no es un número; permitido %3</translation>
    </message>
    <message>
        <source>%1 = %2 is not allowed; allowed %3%4</source>
        <translation>%1 = %2 no está permitido; permitido %3%4</translation>
    </message>
    <message>
        <source>, whole numbers</source>
        <translation>, números enteros</translation>
    </message>
    <message>
        <source>Back to the default: %1</source>
        <translation>Volver al valor por defecto: %1</translation>
    </message>
    <message>
        <source>Back to the default: %1 %2</source>
        <translation>Volver al valor por defecto: %1 %2</translation>
    </message>
    <message>
        <source>%1 from %2 to %3 %4%5 (the field takes any value in %6)</source>
        <translation>%1 de %2 a %3 %4%5 (el campo admite cualquier valor en %6)</translation>
    </message>
    <message>
        <source>, logarithmic</source>
        <translation>, logarítmico</translation>
    </message>
</context>
<context>
    <name>elui::PlotDock</name>
    <message>
        <source>Plots</source>
        <translation>Gráficos</translation>
    </message>
    <message>
        <source>Last 5 s</source>
        <translation>Últimos 5 s</translation>
    </message>
    <message>
        <source>Last 10 s</source>
        <translation>Últimos 10 s</translation>
    </message>
    <message>
        <source>Last 30 s</source>
        <translation>Últimos 30 s</translation>
    </message>
    <message>
        <source>Full history</source>
        <translation>Historia completa</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>Escala automática</translation>
    </message>
    <message>
        <source>Fit the axes to the data; off while you zoom (wheel) and pan (drag)</source>
        <translation>Ajustar los ejes a los datos; desactivado mientras hace zoom (rueda) y desplaza (arrastrar)</translation>
    </message>
    <message>
        <source>Show per-step error band</source>
        <translation>Mostrar banda de error por paso</translation>
    </message>
    <message>
        <source>A band around volume, pressure and total energy: the integrator&apos;s local error estimate of each step carried to them (|O(y + e) - O(y)|): the error one step adds, not the error of the run so far, which can be far larger. rk45, CVODE and step doubling have an estimate; other methods show no band.</source>
        <translation>Una banda alrededor del volumen, la presión y la energía total: la estimación del error local del integrador en cada paso trasladada a ellos (|O(y + e) - O(y)|): el error que añade un paso, no el error acumulado de la ejecución, que puede ser mucho mayor. rk45, CVODE y la duplicación de paso tienen una estimación; los demás métodos no muestran banda.</translation>
    </message>
    <message>
        <source>Time window of the plots</source>
        <translation>Ventana de tiempo de los gráficos</translation>
    </message>
    <message>
        <source>How much of the run the plots show: the last seconds, or all of it</source>
        <translation>Cuánto de la ejecución muestran los gráficos: los últimos segundos o todo</translation>
    </message>
    <message>
        <source>Show</source>
        <translation>Mostrar</translation>
    </message>
    <message>
        <source>Energy drift per view</source>
        <translation>Deriva de energía por vista</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|drift| [J]</source>
        <translation>|deriva| [J]</translation>
    </message>
    <message>
        <source>✕ a view failed</source>
        <translation>✕ una vista falló</translation>
    </message>
    <message>
        <source>%1 against simulated time; the numbers are in the Run dock&apos;s readout and in File &gt; Export Data</source>
        <translation>%1 frente al tiempo simulado; los números están en la lectura del panel Ejecución y en Archivo &gt; Exportar datos</translation>
    </message>
    <message>
        <source>total</source>
        <translation>total</translation>
    </message>
    <message>
        <source> (abandoned)</source>
        <translation> (abandonado)</translation>
    </message>
    <message>
        <source> error band</source>
        <translation> banda de error</translation>
    </message>
    <message>
        <source>No band: this integrator gives no error estimate. Use rk45, CVODE, or tick &quot;Estimate error (step doubling)&quot; in the Run dock.</source>
        <translation>Sin banda: este integrador no da estimación del error. Use rk45, CVODE, o marque «Estimar error (duplicación de paso)» en el panel Ejecución.</translation>
    </message>
    <message>
        <source>The band is there but thinner than a line: each step&apos;s error estimate is below half a pixel at this zoom (an adaptive method keeps it under its tolerance). Loosen rtol/atol in the Run dock, or use a fixed-step method at a larger DT with step doubling, to see it.</source>
        <translation>La banda está, pero es más fina que una línea: la estimación del error de cada paso es menor que medio píxel con este zoom (un método adaptativo la mantiene bajo su tolerancia). Afloje rtol/atol en el panel Ejecución, o use un método de paso fijo con un DT mayor y duplicación de paso, para verla.</translation>
    </message>
    <message>
        <source>Band: the error each step adds (a per-step estimate), not the error of the run so far.</source>
        <translation>Banda: el error que añade cada paso (una estimación por paso), no el error acumulado de la ejecución.</translation>
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
        <translation>Volumen, presión y energía frente al tiempo simulado, un gráfico debajo de otro</translation>
    </message>
    <message>
        <source>Reference curve (rk45)</source>
        <translation>Curva de referencia (rk45)</translation>
    </message>
    <message>
        <source>A converged solution (rk45 at tolerance 1e-10) from the run&apos;s start, computed beside the run on a thread of its own and drawn dashed: the distance between a curve and it is the error of the run so far (the global error), where the band is the error one step adds. It follows the run up to the first change of the physics (a parameter edit other than DT, or a drag).</source>
        <translation>Una solución convergida (rk45 con tolerancia 1e-10) desde el inicio de la ejecución, calculada junto a ella en un hilo propio y dibujada a trazos: la distancia entre una curva y ella es el error acumulado de la ejecución (el error global), mientras que la banda es el error que añade un paso. Sigue a la ejecución hasta el primer cambio de la física (un cambio de parámetro distinto de DT, o un arrastre).</translation>
    </message>
    <message>
        <source>reference (rk45, 1e-10)</source>
        <translation>referencia (rk45, 1e-10)</translation>
    </message>
    <message>
        <source>Reference: computing from the run&apos;s start…</source>
        <translation>Referencia: calculando desde el inicio de la ejecución…</translation>
    </message>
    <message>
        <source>At t = %1 s the run&apos;s total energy is %2 J from the reference: the error of the run so far.</source>
        <translation>En t = %1 s la energía total de la ejecución está a %2 J de la referencia: el error acumulado de la ejecución.</translation>
    </message>
    <message>
        <source>The band there, one step&apos;s error: ±%1 J.</source>
        <translation>La banda ahí, el error de un paso: ±%1 J.</translation>
    </message>
    <message>
        <source>The reference itself failed at t = %1 s (%2): the body fails at every step size.</source>
        <translation>La propia referencia falló en t = %1 s (%2): el cuerpo falla con cualquier paso.</translation>
    </message>
    <message>
        <source>The run was changed at t = %1 s (a parameter edit or a drag): the reference stops there.</source>
        <translation>La ejecución se cambió en t = %1 s (un cambio de parámetro o un arrastre): la referencia termina ahí.</translation>
    </message>
    <message>
        <source>The reference has reached t = %1 s (computing).</source>
        <translation>La referencia ha llegado a t = %1 s (calculando).</translation>
    </message>
</context>
<context>
    <name>elui::PvDock</name>
    <message>
        <source>P–V diagram</source>
        <translation>Diagrama P–V</translation>
    </message>
    <message>
        <source>Whole curve (0.5 to 1.5 × rest volume)</source>
        <translation>Curva completa (0,5 a 1,5 × volumen en reposo)</translation>
    </message>
    <message>
        <source>Off: the axes fit the trail, to see it move. On: a wide stretch of the isotherm, to see where on it the layer sits.</source>
        <translation>Desactivado: los ejes se ajustan a la traza, para verla moverse. Activado: un tramo amplio de la isoterma, para ver en qué punto de ella está la capa.</translation>
    </message>
    <message>
        <source>inner layer</source>
        <translation>capa interior</translation>
    </message>
    <message>
        <source>outer layer</source>
        <translation>capa exterior</translation>
    </message>
    <message>
        <source>Pressure against volume, %1</source>
        <translation>Presión frente a volumen, %1</translation>
    </message>
    <message>
        <source>The trail of the layer&apos;s gas in the P-V plane and its isotherm</source>
        <translation>La traza del gas de la capa en el plano P-V y su isoterma</translation>
    </message>
    <message>
        <source>P–V, %1</source>
        <translation>P–V, %1</translation>
    </message>
    <message>
        <source>trail</source>
        <translation>traza</translation>
    </message>
    <message>
        <source>now</source>
        <translation>ahora</translation>
    </message>
    <message>
        <source>area V [m²]</source>
        <translation>área V [m²]</translation>
    </message>
    <message>
        <source>volume V [m³]</source>
        <translation>volumen V [m³]</translation>
    </message>
    <message>
        <source>pressure P [N/m]</source>
        <translation>presión P [N/m]</translation>
    </message>
    <message>
        <source>pressure P [Pa]</source>
        <translation>presión P [Pa]</translation>
    </message>
    <message>
        <source>%1 has no gas: no P–V diagram.</source>
        <translation>%1 no tiene gas: no hay diagrama P–V.</translation>
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
        <translation>Estudio de refinamiento</translation>
    </message>
    <message>
        <source>Values of the scene&apos;s resolution, separated by spaces; the finest is the reference</source>
        <translation>Valores de la resolución de la escena, separados por espacios; el más fino es la referencia</translation>
    </message>
    <message>
        <source>automatic</source>
        <translation>automático</translation>
    </message>
    <message>
        <source>Fixed step DT [s] for every level; it must divide 0.01 s and be stable at the finest level. Empty: a quarter of the smaller of the scene&apos;s DT and the finest level&apos;s stable step</source>
        <translation>Paso fijo DT [s] para cada nivel; debe dividir 0.01 s y ser estable en el nivel más fino. Vacío: un cuarto del menor entre el DT de la escena y el paso estable del nivel más fino</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Tiempo simulado de cada ejecución [s]</translation>
    </message>
    <message>
        <source>Levels</source>
        <translation>Niveles</translation>
    </message>
    <message>
        <source>Levels (%1)</source>
        <translation>Niveles (%1)</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Duración T [s]</translation>
    </message>
    <message>
        <source>run time [s]</source>
        <translation>tiempo de cálculo [s]</translation>
    </message>
    <message>
        <source>max relative volume error</source>
        <translation>error relativo máx. de volumen</translation>
    </message>
    <message>
        <source>max centre-of-mass error [m]</source>
        <translation>error máx. del centro de masas [m]</translation>
    </message>
    <message>
        <source>Choose exactly one integrator</source>
        <translation>Elija exactamente un integrador</translation>
    </message>
    <message>
        <source>DT must be a number in seconds, or empty for the automatic step</source>
        <translation>DT debe ser un número en segundos, o vacío para el paso automático</translation>
    </message>
    <message>
        <source>Levels are whole numbers separated by spaces, got &apos;%1&apos;</source>
        <translation>Los niveles son números enteros separados por espacios; se recibió «%1»</translation>
    </message>
    <message>
        <source>level (%1)</source>
        <translation>nivel (%1)</translation>
    </message>
    <message>
        <source>particles</source>
        <translation>partículas</translation>
    </message>
    <message>
        <source>springs</source>
        <translation>resortes</translation>
    </message>
    <message>
        <source>h [m]</source>
        <translation>h [m]</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>volume error</source>
        <translation>error de volumen</translation>
    </message>
    <message>
        <source>centre-of-mass error [m]</source>
        <translation>error del centro de masas [m]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>reference</source>
        <translation>referencia</translation>
    </message>
    <message>
        <source>mesh (%1)</source>
        <translation>malla (%1)</translation>
    </message>
    <message>
        <source>step (%1=%2, coarser DT)</source>
        <translation>paso (%1=%2, DT más grueso)</translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation>Falló: %1</translation>
    </message>
    <message>
        <source>Time error of that step (measured at %1=%2): volume %3, centre of mass %4 m. </source>
        <translation>Error temporal de ese paso (medido en %1=%2): volumen %3, centro de masas %4 m. </translation>
    </message>
    <message>
        <source>Spatial order (%1): %2. </source>
        <translation>Orden espacial (%1): %2. </translation>
    </message>
    <message>
        <source>Spatial order (%1): not resolved. </source>
        <translation>Orden espacial (%1): no resuelto. </translation>
    </message>
</context>
<context>
    <name>elui::RunDock</name>
    <message>
        <source>Run</source>
        <translation>Ejecución</translation>
    </message>
    <message>
        <source>side by side (see each view)</source>
        <translation>lado a lado (ver cada vista)</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>Integrador</translation>
    </message>
    <message>
        <source>The method that advances the body in time; each one&apos;s order and idea are in its item&apos;s tooltip and in Help</source>
        <translation>El método que hace avanzar el cuerpo en el tiempo; el orden y la idea de cada uno están en la descripción emergente de su elemento y en la Ayuda</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>rk45, cvode-bdf and cvode-adams choose their steps so that each step&apos;s error estimate stays below atol + rtol |y| (as elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] (m and m/s). Smaller: smaller steps, more force evaluations, a thinner error band.</source>
        <translation>rk45, cvode-bdf y cvode-adams eligen sus pasos de modo que la estimación del error de cada paso quede por debajo de atol + rtol |y| (como elastic-lab-cli --atol, --rtol). rtol en (0, 1], atol en [0, 1] (m y m/s). Menor: pasos más pequeños, más evaluaciones de fuerza, una banda de error más fina.</translation>
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
        <translation>Tolerancia</translation>
    </message>
    <message>
        <source>How fast simulated time runs against the wall clock</source>
        <translation>Qué tan rápido corre el tiempo simulado frente al reloj</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>Velocidad</translation>
    </message>
    <message>
        <source>Run or pause the simulation (Space)</source>
        <translation>Ejecutar o pausar la simulación (Espacio)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>Paso</translation>
    </message>
    <message>
        <source>One step DT forward (S)</source>
        <translation>Un paso DT adelante (S)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>Reiniciar</translation>
    </message>
    <message>
        <source>Back to the start state with the same parameters (Ctrl+R)</source>
        <translation>Volver al estado inicial con los mismos parámetros (Ctrl+R)</translation>
    </message>
    <message>
        <source>Estimate error (step doubling)</source>
        <translation>Estimar error (duplicación de paso)</translation>
    </message>
    <message>
        <source>Fixed-step integrators: estimate the local error by taking each step also as two half steps. Costs about twice the work. rk45 always reports its own estimate.</source>
        <translation>Integradores de paso fijo: estimar el error local dando cada paso también como dos medios pasos. Cuesta aproximadamente el doble de trabajo. rk45 siempre informa de su propia estimación.</translation>
    </message>
    <message>
        <source>Readout</source>
        <translation>Lectura</translation>
    </message>
    <message>
        <source>Time, steps, energies and the energy balance of the run</source>
        <translation>Tiempo, pasos, energías y el balance de energía de la ejecución</translation>
    </message>
    <message>
        <source>rtol: &apos;%1&apos; is not a number in (0, 1]</source>
        <translation>rtol: «%1» no es un número en (0, 1]</translation>
    </message>
    <message>
        <source>atol: &apos;%1&apos; is not a number in [0, 1]</source>
        <translation>atol: «%1» no es un número en [0, 1]</translation>
    </message>
    <message>
        <source>Each view</source>
        <translation>Cada vista</translation>
    </message>
    <message>
        <source>view</source>
        <translation>vista</translation>
    </message>
    <message>
        <source>time</source>
        <translation>tiempo</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>deriva de energía</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>falló</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>Pausa</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>tiempo simulado</translation>
    </message>
    <message>
        <source>wall time</source>
        <translation>tiempo de reloj</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>pasos/s</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>en pausa</translation>
    </message>
    <message>
        <source>step taken</source>
        <translation>paso dado</translation>
    </message>
    <message>
        <source>error estimate</source>
        <translation>estimación del error</translation>
    </message>
    <message>
        <source>off</source>
        <translation>desactivado</translation>
    </message>
    <message>
        <source>contact energy</source>
        <translation>energía de contacto</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>quitado por el contacto</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>evaluaciones de fuerza</translation>
    </message>
    <message>
        <source>CVODE steps / RHS</source>
        <translation>pasos CVODE / RHS</translation>
    </message>
    <message>
        <source>Jv products / linear it.</source>
        <translation>productos Jv / it. lineales</translation>
    </message>
    <message>
        <source>error-test / conv. failures</source>
        <translation>fallos test de error / conv.</translation>
    </message>
    <message>
        <source>order, re-initialisations</source>
        <translation>orden, reinicializaciones</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b35900&apos;&gt;Cannot keep up with real time: showing as fast as it runs.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b35900&apos;&gt;No puede seguir el tiempo real: se muestra tan rápido como calcula.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>order %1: %2</source>
        <translation>orden %1: %2</translation>
    </message>
    <message>
        <source>%1; allowed %2 s</source>
        <translation>%1; permitido %2 s</translation>
    </message>
    <message>
        <source>Relative tolerance rtol</source>
        <translation>Tolerancia relativa rtol</translation>
    </message>
    <message>
        <source>Absolute tolerance atol</source>
        <translation>Tolerancia absoluta atol</translation>
    </message>
    <message>
        <source>Run</source>
        <comment>button: start the simulation</comment>
        <translation>Ejecutar</translation>
    </message>
    <message>
        <source>distance&lt;br&gt;to view %1</source>
        <translation>distancia&lt;br&gt;a la vista %1</translation>
    </message>
    <message>
        <source>double</source>
        <translation>doble (64 bits)</translation>
    </message>
    <message>
        <source>float</source>
        <translation>simple (32 bits)</translation>
    </message>
    <message>
        <source>double: state and forces in 64-bit numbers. float: in 32-bit numbers, as fast engines and games compute (euler, midpoint, rk4, symplectic-euler, verlet; one view; no walls or mouse: the run stops at a wall, a held particle steps in double). The readout shows how far the float run is from double.</source>
        <translation>doble: estado y fuerzas en números de 64 bits. simple: en números de 32 bits, como calculan los motores rápidos y los juegos (euler, midpoint, rk4, symplectic-euler, verlet; una sola vista; sin paredes ni ratón: la simulación se detiene en una pared, una partícula sujeta avanza en doble). La lectura muestra la distancia entre la simulación en simple y la de doble.</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>Precisión</translation>
    </message>
    <message>
        <source>precision</source>
        <translation>precisión</translation>
    </message>
    <message>
        <source>double while held</source>
        <translation>doble mientras se sujeta</translation>
    </message>
    <message>
        <source>float − double</source>
        <translation>simple − doble</translation>
    </message>
    <message>
        <source>round-off (est.)</source>
        <translation>redondeo (estimado)</translation>
    </message>
</context>
<context>
    <name>elui::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>Escena</translation>
    </message>
    <message>
        <source>The body to build: a spring, a two-layer ring or a two-layer sphere</source>
        <translation>El cuerpo que se construye: un resorte, un anillo de dos capas o una esfera de dos capas</translation>
    </message>
    <message>
        <source>Rebuild body</source>
        <translation>Reconstruir cuerpo</translation>
    </message>
    <message>
        <source>Build the chosen scene with this shape and start again from rest</source>
        <translation>Construir la escena elegida con esta forma y empezar de nuevo desde el reposo</translation>
    </message>
    <message>
        <source>Body values</source>
        <translation>Valores del cuerpo</translation>
    </message>
    <message>
        <source>What the parameters mean for the body that runs: under scaling=physical the values hold at the scene&apos;s default resolution and a finer mesh keeps the body&apos;s totals; under scaling=thesis they are per particle and per spring</source>
        <translation>Qué significan los parámetros para el cuerpo en marcha: con scaling=physical los valores valen para la resolución por defecto de la escena y una malla más fina conserva los totales del cuerpo; con scaling=thesis son por partícula y por resorte</translation>
    </message>
    <message>
        <source>This body uses: %1</source>
        <translation>Este cuerpo usa: %1</translation>
    </message>
    <message>
        <source>The body to build, its shape and what its parameters mean</source>
        <translation>El cuerpo que se construye, su forma y qué significan sus parámetros</translation>
    </message>
</context>
<context>
    <name>elui::StabilityDialog</name>
    <message>
        <source>Stability scan</source>
        <translation>Barrido de estabilidad</translation>
    </message>
    <message>
        <source>Each trial runs this long; a run that does not blow up and whose energy stays bounded is stable</source>
        <translation>Cada prueba dura esto; una ejecución que no explota y cuya energía se mantiene acotada es estable</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Duración T [s]</translation>
    </message>
    <message>
        <source>largest stable DT [s]</source>
        <translation>mayor DT estable [s]</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>linearising</source>
        <translation>linealizando</translation>
    </message>
    <message>
        <source>stable DT [s]</source>
        <translation>DT estable [s]</translation>
    </message>
    <message>
        <source>unstable DT [s]</source>
        <translation>DT inestable [s]</translation>
    </message>
    <message>
        <source>predicted DT [s]</source>
        <translation>DT predicho [s]</translation>
    </message>
    <message>
        <source>h·ω at stable</source>
        <translation>h·ω en estable</translation>
    </message>
    <message>
        <source>why it failed above</source>
        <translation>por qué falló por encima</translation>
    </message>
    <message>
        <source>measured</source>
        <translation>medido</translation>
    </message>
    <message>
        <source>linearised prediction</source>
        <translation>predicción linealizada</translation>
    </message>
    <message>
        <source>Highest mode of the linearised body: ω = %1 rad/s (damping %2 1/s), %3 free coordinates. A method is stable at DT when no mode grows; measured by bisection over %4 s runs.</source>
        <translation>Modo más alto del cuerpo linealizado: ω = %1 rad/s (amortiguamiento %2 1/s), %3 coordenadas libres. Un método es estable con DT cuando ningún modo crece; medido por bisección con ejecuciones de %4 s.</translation>
    </message>
    <message>
        <source>Duration must be a positive number of seconds</source>
        <translation>La duración debe ser un número positivo de segundos</translation>
    </message>
</context>
<context>
    <name>elui::StabilityMapDock</name>
    <message>
        <source>Stability map</source>
        <translation>Mapa de estabilidad</translation>
    </message>
    <message>
        <source>The integrator&apos;s stability region and the body&apos;s eigenvalues times DT; the margin is written below the map</source>
        <translation>La región de estabilidad del integrador y los valores propios del cuerpo por DT; el margen está escrito bajo el mapa</translation>
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
        <translation>región estable</translation>
    </message>
    <message>
        <source>DT·λ, every mode</source>
        <translation>DT·λ, todos los modos</translation>
    </message>
    <message>
        <source>leaves first</source>
        <translation>sale primero</translation>
    </message>
    <message>
        <source>measured limit</source>
        <translation>límite medido</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>Probar</translation>
    </message>
    <message>
        <source>Waiting for a body…</source>
        <translation>Esperando un cuerpo…</translation>
    </message>
    <message>
        <source>Linearising the body…</source>
        <translation>Linealizando el cuerpo…</translation>
    </message>
    <message>
        <source>edge (radius 1)</source>
        <translation>borde (radio 1)</translation>
    </message>
    <message>
        <source>edge |R| = 1</source>
        <translation>borde |R| = 1</translation>
    </message>
    <message>
        <source>edge of view %1 (%2)</source>
        <translation>borde de la vista %1 (%2)</translation>
    </message>
    <message>
        <source>Re(hλ), h = DT = %1 s</source>
        <translation>Re(hλ), h = DT = %1 s</translation>
    </message>
    <message>
        <source>View %1, %2 (filled): %3</source>
        <translation>Vista %1, %2 (relleno): %3</translation>
    </message>
    <message>
        <source>View %1, %2 (dashed): %3</source>
        <translation>Vista %1, %2 (a trazos): %3</translation>
    </message>
    <message>
        <source>Eigenvalues: %1.
%2</source>
        <translation>Valores propios: %1.
%2</translation>
    </message>
    <message>
        <source>%1 has no fixed stability limit to measure</source>
        <translation>%1 no tiene un límite de estabilidad fijo que medir</translation>
    </message>
    <message>
        <source>Measured: no stable DT down to 1e-5 s.</source>
        <translation>Medido: ningún DT estable hasta 1e-5 s.</translation>
    </message>
    <message>
        <source>Measured: stable up to the largest DT scanned, %1 s</source>
        <translation>Medido: estable hasta el mayor DT barrido, %1 s</translation>
    </message>
    <message>
        <source>Measured: stable at DT = %1 s, blows up at %2 s</source>
        <translation>Medido: estable con DT = %1 s, explota con %2 s</translation>
    </message>
    <message>
        <source> (%1 runs of %2 s; predicted %3 s).</source>
        <translation> (%1 ejecuciones de %2 s; predicho %3 s).</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>ilimitado</translation>
    </message>
    <message>
        <source> ✕ = the ringed mode at the measured DT.</source>
        <translation> ✕ = el modo rodeado con el DT medido.</translation>
    </message>
    <message>
        <source> ✕ = the fastest mode at the measured DT.</source>
        <translation> ✕ = el modo más rápido con el DT medido.</translation>
    </message>
    <message>
        <source>Measuring the largest stable DT of %1…</source>
        <translation>Midiendo el mayor DT estable de %1…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>Cancelando…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Measurement cancelled.</source>
        <translation>Medición cancelada.</translation>
    </message>
    <message>
        <source>The body or the integrator changed during the measurement: press Try it again.</source>
        <translation>El cuerpo o el integrador cambió durante la medición: pulse Probar otra vez.</translation>
    </message>
    <message>
        <source>Measure this integrator&apos;s largest stable DT on this body or world: the stability scan&apos;s bisection (%1 s runs; Studies → Stability scan does all integrators), marked on the picture</source>
        <translation>Medir el mayor DT estable de este integrador en este cuerpo o mundo: la bisección del barrido de estabilidad (ensayos de %1 s; Estudios → Barrido de estabilidad hace todos los integradores), marcado en la imagen</translation>
    </message>
    <message>
        <source>Linearising the world (%1 bodies)…</source>
        <translation>Linealizando el mundo (%1 cuerpos)…</translation>
    </message>
    <message>
        <source>The whole world (%1 bodies) linearised as one system: every body&apos;s modes, and the contact between bodies where two are within the contact skin. </source>
        <translation>El mundo entero (%1 cuerpos) linealizado como un solo sistema: los modos de cada cuerpo y el contacto entre cuerpos donde dos están dentro de la piel de contacto. </translation>
    </message>
    <message>
        <source>the fastest mode</source>
        <translation>el modo más rápido</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1, a pure decay)</source>
        <translation>el modo más rápido (hλ = %1, decaimiento puro)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1, a pure decay)</source>
        <translation>el modo (hλ = %1, decaimiento puro)</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1 ± %2i)</source>
        <translation>el modo más rápido (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1 ± %2i)</source>
        <translation>el modo (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>per mode, modal damping</source>
        <translation>modo a modo, amortiguamiento modal</translation>
    </message>
    <message>
        <source>xpbd is stable at every DT: no margin to give.</source>
        <translation>xpbd es estable con cualquier DT: no hay margen que indicar.</translation>
    </message>
    <message>
        <source>%1 chooses its own internal steps: no DT limit from stability.</source>
        <translation>%1 elige sus propios pasos internos: la estabilidad no limita DT.</translation>
    </message>
    <message>
        <source>No DT limit: every mode of this body stays in the region for any DT.</source>
        <translation>Sin límite de DT: todos los modos de este cuerpo permanecen en la región con cualquier DT.</translation>
    </message>
    <message>
        <source>No DT is stable: a mode pair grows for every DT (%1).</source>
        <translation>Ningún DT es estable: un par de modos crece con cualquier DT (%1).</translation>
    </message>
    <message>
        <source>No DT is stable: %1 sits where the region only touches the imaginary axis at 0; it grows for every DT (slowly when DT is small).</source>
        <translation>Ningún DT es estable: %1 está donde la región solo toca el eje imaginario en 0; crece con cualquier DT (lentamente si DT es pequeño).</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before a mode pair goes unstable (%3); the picture is exact for underdamped modes only.</source>
        <translation>DT puede multiplicarse por %1 (hasta %2 s) antes de que un par de modos se vuelva inestable (%3); la imagen solo es exacta para modos subamortiguados.</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before %3 leaves the region.</source>
        <translation>DT puede multiplicarse por %1 (hasta %2 s) antes de que %3 salga de la región.</translation>
    </message>
    <message>
        <source>DT is already outside the stable range (%1): shrink DT by %2× (to %3 s).</source>
        <translation>DT ya está fuera del rango estable (%1): reduzca DT en un factor %2 (a %3 s).</translation>
    </message>
    <message>
        <source>DT is already outside: %1 is out of the region; shrink DT by %2× (to %3 s) to bring it back.</source>
        <translation>DT ya es demasiado grande: %1 está fuera de la región; reduzca DT en un factor %2 (a %3 s) para que vuelva a entrar.</translation>
    </message>
    <message>
        <source>exact spectrum: all %1 eigenvalues of the linearised first-order system (dense eigen-solve)</source>
        <translation>espectro exacto: los %1 valores propios del sistema linealizado de primer orden (cálculo denso)</translation>
    </message>
    <message>
        <source>modal: all %1 modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; λ = −c/2 ± i√(ω² − c²/4)</source>
        <translation>modal: los %1 modos de M⁻¹K (problema de valores propios simétrico), amortiguamiento c = φᵀ(M⁻¹D)φ por modo; λ = −c/2 ± i√(ω² − c²/4)</translation>
    </message>
    <message>
        <source>iterative: %1 Ritz values of the first-order system, Arnoldi (%2 steps) on the Jacobian products, %3 free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner ones are not</source>
        <translation>iterativo: %1 valores de Ritz del sistema de primer orden, Arnoldi (%2 pasos) sobre los productos por la jacobiana, %3 coordenadas libres: los valores propios extremos (mayor |λ|) son precisos, los interiores no</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis up to ±%1i: undamped modes are stable up to hω = 2√2.</source>
        <translation>Región: |R(hλ)| ≤ 1 para su polinomio de estabilidad R (el polinomio de Taylor de e^z); toca el eje imaginario hasta ±%1i: los modos no amortiguados son estables hasta hω = 2√2.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis only at 0: an undamped mode grows for every DT.</source>
        <translation>Región: |R(hλ)| ≤ 1 para su polinomio de estabilidad R (el polinomio de Taylor de e^z); solo toca el eje imaginario en 0: un modo no amortiguado crece con cualquier DT.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for Dormand–Prince&apos;s 5th-order solution, R = Taylor to z⁵ + z⁶/600, taken at a fixed step. The adaptive run picks its own step from the error tolerance: it does not blow up, it takes smaller steps.</source>
        <translation>Región: |R(hλ)| ≤ 1 para la solución de orden 5 de Dormand–Prince, R = Taylor hasta z⁵ + z⁶/600, tomada con paso fijo. La ejecución adaptativa elige su propio paso según la tolerancia de error: no explota, da pasos más pequeños.</translation>
    </message>
    <message>
        <source>Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| &lt; 1, the whole left half-plane (A-stable): no DT limit from stability.</source>
        <translation>Región: |1/(1 − hλ)| ≤ 1, todo el exterior del disco |1 − hλ| &lt; 1, es decir, todo el semiplano izquierdo (A-estable): la estabilidad no limita DT.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Región: no hay R escalar; dibujada para un modo de oscilador cuyo par de valores propios es hλ, hλ̄ (exacta cuando los modos se desacoplan; el eje real muestra el modo con amortiguamiento crítico). Modos no amortiguados: hω ≤ 2. El margen sale de la matriz de paso, no de la imagen.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, damping at the half-step velocity (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>Región: no hay R escalar; dibujada para un modo de oscilador cuyo par de valores propios es hλ, hλ̄, con el amortiguamiento tomado a la velocidad del medio paso (exacta cuando los modos se desacoplan; el eje real muestra el modo con amortiguamiento crítico). Modos no amortiguados: hω ≤ 2. El margen sale de la matriz de paso, no de la imagen.</translation>
    </message>
    <message>
        <source>Region: no scalar R; the step is a product of %1 Verlet substeps (some backwards), drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the half-kick velocity, as the integrator does), traced ray by ray from 0. Undamped modes: hω ≤ %2 (a step costs %3 force evaluations). The margin uses the step matrix, not the picture.</source>
        <translation>Región: no hay R escalar; el paso es un producto de %1 subpasos de Verlet (algunos hacia atrás), dibujada para un modo de oscilador cuyo par de valores propios es hλ, hλ̄ (amortiguamiento a la velocidad de cada medio impulso, como hace el integrador), trazada rayo a rayo desde 0. Modos no amortiguados: hω ≤ %2 (un paso cuesta %3 evaluaciones de fuerza). El margen sale de la matriz de paso, no de la imagen.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed region. BDF1–2 are A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the step or the order when a mode threatens: no DT limit, DT is only the output interval.</source>
        <translation>Sin región: BDF adaptativo de orden variable (órdenes 1–5), con control de error, sin región fija. BDF1–2 son A-estables, BDF3–5 A(α)-estables hasta α ≈ 51°; CVODE reduce el paso o el orden cuando un modo amenaza con crecer: sin límite de DT, DT es solo el intervalo de salida.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed region. Its regions are small (explicit-like); CVODE keeps the internal step inside them by its error test: no DT limit, stiff bodies only cost steps.</source>
        <translation>Sin región: Adams adaptativo de orden variable (órdenes 1–12), con control de error, sin región fija. Sus regiones son pequeñas (como las de un método explícito); CVODE mantiene dentro de ellas el paso interno mediante su prueba de error: sin límite de DT, los cuerpos rígidos solo cuestan pasos.</translation>
    </message>
    <message>
        <source>No region: XPBD projects the springs as compliant constraints (compliance 1/ks): unconditionally stable, no region in the hλ plane; large DT costs accuracy (the body turns soft), not stability.</source>
        <translation>Sin región: XPBD proyecta los resortes como restricciones flexibles (flexibilidad 1/ks): incondicionalmente estable, sin región en el plano hλ; un DT grande cuesta precisión (el cuerpo se vuelve blando), no estabilidad.</translation>
    </message>
    <message>
        <source>No stability region for %1.</source>
        <translation>No hay región de estabilidad para %1.</translation>
    </message>
</context>
<context>
    <name>elui::StrainLegend</name>
    <message>
        <source>spring strain</source>
        <translation>deformación del resorte</translation>
    </message>
</context>
<context>
    <name>elui::StudyDialogBase</name>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt; with the current parameters</source>
        <translation>Escena: &lt;b&gt;%1&lt;/b&gt; con los parámetros actuales</translation>
    </message>
    <message>
        <source>Include %1 (order %2) in the study: %3</source>
        <translation>Incluir %1 (orden %2) en el estudio: %3</translation>
    </message>
    <message>
        <source>Run</source>
        <translation>Ejecución</translation>
    </message>
    <message>
        <source>Run the study on a worker thread; the window stays usable</source>
        <translation>Ejecutar el estudio en un hilo de trabajo; la ventana sigue utilizable</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>Cancelar</translation>
    </message>
    <message>
        <source>Stop the study; the rows finished so far stay</source>
        <translation>Detener el estudio; las filas terminadas se quedan</translation>
    </message>
    <message>
        <source>Export...</source>
        <translation>Exportar...</translation>
    </message>
    <message>
        <source>Write the table as CSV, or the plot as SVG, PNG or PDF</source>
        <translation>Escribir la tabla como CSV, o el gráfico como SVG, PNG o PDF</translation>
    </message>
    <message>
        <source>Study plot</source>
        <translation>Gráfico del estudio</translation>
    </message>
    <message>
        <source>The study&apos;s results drawn; the same numbers are in the table</source>
        <translation>Los resultados del estudio dibujados; los mismos números están en la tabla</translation>
    </message>
    <message>
        <source>Results</source>
        <translation>Resultados</translation>
    </message>
    <message>
        <source>One row per run of the study; the arrow keys move between the cells</source>
        <translation>Una fila por ejecución del estudio; las flechas se mueven entre las celdas</translation>
    </message>
    <message>
        <source>Cancelled: partial results</source>
        <translation>Cancelado: resultados parciales</translation>
    </message>
    <message>
        <source>Done</source>
        <translation>Hecho</translation>
    </message>
    <message>
        <source>Choose at least one integrator</source>
        <translation>Elija al menos un integrador</translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation>Cancelando...</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>Tabla CSV (*.csv);;Gráfico PNG (*.png);;Gráfico PDF (*.pdf)</translation>
    </message>
    <message>
        <source>CSV table (*.csv);;SVG plot (*.svg);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation>Tabla CSV (*.csv);;Gráfico SVG (*.svg);;Gráfico PNG (*.png);;Gráfico PDF (*.pdf)</translation>
    </message>
    <message>
        <source>Export results</source>
        <translation>Exportar resultados</translation>
    </message>
    <message>
        <source>Export</source>
        <translation>Exportar</translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>Se escribió %1</translation>
    </message>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt;, %2 bodies, with the current parameters (the whole world: every run moves every body)</source>
        <translation>Escena: &lt;b&gt;%1&lt;/b&gt;, %2 cuerpos, con los parámetros actuales (el mundo entero: cada ejecución mueve cada cuerpo)</translation>
    </message>
</context>
<context>
    <name>elui::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>Línea de tiempo</translation>
    </message>
    <message>
        <source>|◀ Start</source>
        <translation>|◀ Inicio</translation>
    </message>
    <message>
        <source>The start of the recorded run (Home)</source>
        <translation>El inicio de la ejecución grabada (Inicio)</translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ Paso atrás</translation>
    </message>
    <message>
        <source>One step back (Shift+S); S steps forward</source>
        <translation>Un paso atrás (Mayús+S); S avanza</translation>
    </message>
    <message>
        <source>Newest ▶|</source>
        <translation>Más reciente ▶|</translation>
    </message>
    <message>
        <source>The newest recorded moment (End)</source>
        <translation>El momento grabado más reciente (Fin)</translation>
    </message>
    <message>
        <source>Clear abandoned</source>
        <translation>Borrar lo abandonado</translation>
    </message>
    <message>
        <source>Remove the faint lines of the abandoned future from the plots</source>
        <translation>Quitar de los gráficos las líneas tenues del futuro abandonado</translation>
    </message>
    <message>
        <source>&lt;b&gt;Back in time&lt;/b&gt;: t = %1 s, step %2 of %3 · a change, Run or Step branches here</source>
        <translation>&lt;b&gt;Atrás en el tiempo&lt;/b&gt;: t = %1 s, paso %2 de %3 · un cambio, Ejecutar o Paso crea una rama aquí</translation>
    </message>
    <message>
        <source>t = %1 s, step %2 (newest) · recorded from t = %3 s</source>
        <translation>t = %1 s, paso %2 (más reciente) · grabado desde t = %3 s</translation>
    </message>
    <message>
        <source>%1 checkpoints / %2 steps · %3 of %4</source>
        <translation>%1 puntos de control / %2 pasos · %3 de %4</translation>
    </message>
    <message>
        <source>Every moment of the run: drag, or Tab to it and press the arrow keys (Page Up and Page Down: a twentieth of the run), to travel back in time (the run pauses)</source>
        <translation>Cada momento de la ejecución: arrastre, o llegue con Tab y pulse las flechas (Re Pág y Av Pág: una vigésima parte de la ejecución), para viajar atrás en el tiempo (la ejecución se pausa)</translation>
    </message>
</context>
<context>
    <name>elui::Viewport</name>
    <message>
        <source>Simulation view</source>
        <translation>Vista de la simulación</translation>
    </message>
    <message>
        <source>The body. Keyboard: arrow keys or Page Up and Page Down choose a particle and show the forces on it; Enter grabs it with the mouse spring, then the arrow keys drag it (Shift: ten times farther) and Enter or Escape lets go; Escape clears the choice.</source>
        <translation>El cuerpo. Teclado: las flechas o Re Pág y Av Pág eligen una partícula y muestran las fuerzas sobre ella; Intro la agarra con el resorte del ratón, después las flechas la arrastran (Mayús: diez veces más lejos) e Intro o Escape la suelta; Escape borra la elección.</translation>
    </message>
    <message>
        <source>Forces on particle %1</source>
        <translation>Fuerzas sobre la partícula %1</translation>
    </message>
    <message>
        <source>total (sum)</source>
        <translation>total (suma)</translation>
    </message>
    <message>
        <source>arrows: 1 m = %1 N</source>
        <translation>flechas: 1 m = %1 N</translation>
    </message>
    <message>
        <source>click elsewhere to clear</source>
        <translation>haga clic en otro lugar para borrar</translation>
    </message>
    <message>
        <source>distance from %1: %2 m (RMS)</source>
        <translation>distancia a %1: %2 m (RMS)</translation>
    </message>
    <message>
        <source>Blew up at t = %1 s: %2</source>
        <translation>Explotó en t = %1 s: %2</translation>
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
        <translation>Fuerzas sobre la partícula %1 del cuerpo %2</translation>
    </message>
    <message>
        <source>momentum %1 kg m/s</source>
        <translation>cantidad de movimiento %1 kg m/s</translation>
    </message>
    <message>
        <source>min_gap %1 m</source>
        <translation>min_gap %1 m</translation>
    </message>
    <message>
        <source>min_gap beyond %1 m</source>
        <translation>min_gap más allá de %1 m</translation>
    </message>
</context>
<context>
    <name>elui::WorkPrecisionDialog</name>
    <message>
        <source>Work-precision study</source>
        <translation>Estudio trabajo-precisión</translation>
    </message>
    <message>
        <source>Fixed steps DT [s], separated by spaces; T must be a multiple of each</source>
        <translation>Pasos fijos DT [s], separados por espacios; T debe ser múltiplo de cada uno</translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation>Tiempo simulado de cada ejecución [s]</translation>
    </message>
    <message>
        <source>What the errors are measured against: the closed form where there is one (exact), or a run of rk4 or rk45 with a much smaller step; auto chooses</source>
        <translation>Contra qué se miden los errores: la solución cerrada cuando existe (exact), o una ejecución de rk4 o rk45 con un paso mucho menor; auto elige</translation>
    </message>
    <message>
        <source>Reference</source>
        <translation>Referencia</translation>
    </message>
    <message>
        <source>Each point is timed this many times; the plot shows the median run time with a band from the first to the third quartile (the same binary runs at two speeds on a shared machine)</source>
        <translation>Cada punto se cronometra tantas veces; el gráfico muestra el tiempo de cálculo mediano con una banda del primer al tercer cuartil (el mismo programa corre a dos velocidades en una máquina compartida)</translation>
    </message>
    <message>
        <source>none</source>
        <translation>ninguno</translation>
    </message>
    <message>
        <source>A run that takes longer [s] is recorded as not reached (no error), and so is every costlier point of its integrator: the curve stops there</source>
        <translation>Una ejecución que tarda más [s] se anota como no alcanzada (sin error), y también cada punto más costoso de su integrador: la curva termina ahí</translation>
    </message>
    <message>
        <source>DT values [s]</source>
        <translation>Valores de DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation>Duración T [s]</translation>
    </message>
    <message>
        <source>Timed runs per point</source>
        <translation>Ejecuciones cronometradas por punto</translation>
    </message>
    <message>
        <source>Time budget per run [s]</source>
        <translation>Presupuesto de tiempo por ejecución [s]</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>evaluaciones de fuerza</translation>
    </message>
    <message>
        <source>run time (median, band q1–q3)</source>
        <translation>tiempo de cálculo (mediana, banda q1–q3)</translation>
    </message>
    <message>
        <source>The cost of a run on the left panel: the force evaluations it took (a count: the same on every machine and every run), or its run time, the median over the timed runs with a band from q1 to q3 (on a busy machine a curve can zigzag backwards)</source>
        <translation>El coste de una ejecución en el panel izquierdo: las evaluaciones de fuerza que necesitó (un recuento: el mismo en cualquier máquina y ejecución), o su tiempo de cálculo, la mediana de las ejecuciones cronometradas con una banda de q1 a q3 (en una máquina ocupada una curva puede zigzaguear hacia atrás)</translation>
    </message>
    <message>
        <source>Cost axis</source>
        <translation>Eje del coste</translation>
    </message>
    <message>
        <source>max position error [m]</source>
        <translation>error máx. de posición [m]</translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>run time [s] (median, band q1–q3)</source>
        <translation>tiempo de cálculo [s] (mediana, banda q1–q3)</translation>
    </message>
    <message>
        <source>integrator</source>
        <translation>integrador</translation>
    </message>
    <message>
        <source>family</source>
        <translation>familia</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>pasos</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation>eval. de fuerza</translation>
    </message>
    <message>
        <source>run time q1 [s]</source>
        <translation>tiempo q1 [s]</translation>
    </message>
    <message>
        <source>median [s]</source>
        <translation>mediana [s]</translation>
    </message>
    <message>
        <source>q3 [s]</source>
        <translation>q3 [s]</translation>
    </message>
    <message>
        <source>error at T [m]</source>
        <translation>error en T [m]</translation>
    </message>
    <message>
        <source>max error [m]</source>
        <translation>error máx. [m]</translation>
    </message>
    <message>
        <source>RMS error [m]</source>
        <translation>error RMS [m]</translation>
    </message>
    <message>
        <source>energy error [J]</source>
        <translation>error de energía [J]</translation>
    </message>
    <message>
        <source>status</source>
        <translation>estado</translation>
    </message>
    <message>
        <source>Reference: %1 (its own error about %2 m). Run time: median of %3 timed runs per point, band q1–q3.</source>
        <translation>Referencia: %1 (su propio error es de unos %2 m). Tiempo de cálculo: mediana de %3 ejecuciones cronometradas por punto, banda q1–q3.</translation>
    </message>
    <message>
        <source> %1: order %2 (RMS %3).</source>
        <translation> %1: orden %2 (RMS %3).</translation>
    </message>
    <message>
        <source> q1–q3</source>
        <translation> q1–q3</translation>
    </message>
    <message>
        <source>fastest of its family</source>
        <translation>el más rápido de su familia</translation>
    </message>
</context>
<context>
    <name>simcore</name>
    <message>
        <source>structural spring stiffness KS, per spring (scaling=physical: at the reference resolution; a 2D chain keeps k L0, a 3D membrane keeps k)</source>
        <translation>rigidez KS de los resortes estructurales, por resorte (scaling=physical: en la resolución de referencia; una cadena 2D conserva k L0, una membrana 3D conserva k)</translation>
    </message>
    <message>
        <source>structural spring damping KD, per spring; scales like KS</source>
        <translation>amortiguamiento KD de los resortes estructurales, por resorte; escala como KS</translation>
    </message>
    <message>
        <source>radius and shear spring stiffness RKS, per spring (scaling=physical: at the reference resolution; in parallel, k times count stays fixed)</source>
        <translation>rigidez RKS de los resortes radiales y de cizalla, por resorte (scaling=physical: en la resolución de referencia; en paralelo, k por el número se mantiene fijo)</translation>
    </message>
    <message>
        <source>radius and shear spring damping RKD, per spring; scales like RKS</source>
        <translation>amortiguamiento RKD de los resortes radiales y de cizalla, por resorte; escala como RKS</translation>
    </message>
    <message>
        <source>gas constant nRT of each closed layer (PRESSURE): P = nRT / V</source>
        <translation>constante del gas nRT de cada capa cerrada (PRESSURE): P = nRT / V</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the inner layer (defaults to pressure)</source>
        <translation>nRT del gas encerrado por la capa interior (por defecto: pressure)</translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the outer layer (defaults to pressure)</source>
        <translation>nRT del gas encerrado por la capa exterior (por defecto: pressure)</translation>
    </message>
    <message>
        <source>particle mass MASS (scaling=physical: at the reference resolution; each layer keeps its total)</source>
        <translation>masa de cada partícula MASS (scaling=physical: en la resolución de referencia; cada capa conserva su total)</translation>
    </message>
    <message>
        <source>inner-layer particle mass (defaults to mass; scaled like mass): real inertia, not scaled gravity</source>
        <translation>masa de las partículas de la capa interior (por defecto: mass; escala como mass): inercia real, no gravedad escalada</translation>
    </message>
    <message>
        <source>outer-layer particle mass (defaults to mass; scaled like mass)</source>
        <translation>masa de las partículas de la capa exterior (por defecto: mass; escala como mass)</translation>
    </message>
    <message>
        <source>gravitational acceleration, pointing along -y</source>
        <translation>aceleración de la gravedad, dirigida a lo largo de -y</translation>
    </message>
    <message>
        <source>half-size of the collision box (floor, ceiling, walls), centred on the body&apos;s start</source>
        <translation>mitad del lado de la caja de colisión (suelo, techo, paredes), centrada en la posición inicial del cuerpo</translation>
    </message>
    <message>
        <source>contact model: 0 = force (smooth penalty force inside the ODE, in the energy ledger), 1 = projection (the thesis program: put back and reflect after the step)</source>
        <translation>modelo de contacto: 0 = force (fuerza de penalización suave dentro de la EDO, en el balance de energía), 1 = projection (el programa de la tesis: recolocar y reflejar tras el paso)</translation>
    </message>
    <message>
        <source>coefficient of restitution e at the box walls: a particle hitting at contact_speed rebounds at e times its speed (projection: v_n becomes -e*v_n)</source>
        <translation>coeficiente de restitución e en las paredes de la caja: una partícula que choca a contact_speed rebota a e veces su velocidad (projection: v_n pasa a -e*v_n)</translation>
    </message>
    <message>
        <source>k of the contact potential U = k d^4/4 per particle at a wall (d: penetration) and of the layer barrier (scaling=physical: at the reference resolution, scaled like mass)</source>
        <translation>k del potencial de contacto U = k d^4/4 por partícula en una pared (d: penetración) y de la barrera entre capas (scaling=physical: en la resolución de referencia, escala como mass)</translation>
    </message>
    <message>
        <source>impact speed at which the contact damping gives exactly the restitution e</source>
        <translation>velocidad de impacto a la que el amortiguamiento de contacto da exactamente la restitución e</translation>
    </message>
    <message>
        <source>wall friction: Coulomb coefficient mu (force); tangential velocity fraction removed (projection)</source>
        <translation>rozamiento con las paredes: coeficiente de Coulomb mu (force); fracción de la velocidad tangencial que se quita (projection)</translation>
    </message>
    <message>
        <source>slip speed below which Coulomb friction is smoothed (regularised) [force contact]</source>
        <translation>velocidad de deslizamiento por debajo de la cual el rozamiento de Coulomb se suaviza (regulariza) [contacto force]</translation>
    </message>
    <message>
        <source>mouse spring stiffness (MKS)</source>
        <translation>rigidez del resorte del ratón (MKS)</translation>
    </message>
    <message>
        <source>mouse spring damping (MKD)</source>
        <translation>amortiguamiento del resorte del ratón (MKD)</translation>
    </message>
    <message>
        <source>rest length of the mouse spring</source>
        <translation>longitud en reposo del resorte del ratón</translation>
    </message>
    <message>
        <source>time step DT of fixed-step integrators (initial step of adaptive ones)</source>
        <translation>paso de tiempo DT de los integradores de paso fijo (paso inicial de los adaptativos)</translation>
    </message>
    <message>
        <source>xpbd: substeps per step DT, one constraint iteration each (Macklin et al. 2019, small steps)</source>
        <translation>xpbd: subpasos por paso DT, una iteración de las restricciones cada uno (Macklin et al. 2019, pasos pequeños)</translation>
    </message>
    <message>
        <source>what mass, ks, kd, rks, rkd and contact_stiffness mean when the mesh is refined: 0 = physical (the values hold at the scene&apos;s default resolution and the body keeps its totals and material constants), 1 = thesis (per particle and per spring at every resolution)</source>
        <translation>qué significan mass, ks, kd, rks, rkd y contact_stiffness cuando se refina la malla: 0 = physical (los valores valen para la resolución por defecto de la escena y el cuerpo conserva sus totales y constantes del material), 1 = thesis (por partícula y por resorte en cualquier resolución)</translation>
    </message>
    <message>
        <source>particles per layer of the 2D ring</source>
        <translation>partículas por capa del anillo 2D</translation>
    </message>
    <message>
        <source>subdivision level L of the octahedron sphere: 4*4^L+2 particles per layer</source>
        <translation>nivel de subdivisión L de la esfera octaédrica: 4*4^L+2 partículas por capa</translation>
    </message>
    <message>
        <source>meridians of the lat/long sphere</source>
        <translation>meridianos de la esfera de longitud/latitud</translation>
    </message>
    <message>
        <source>latitude bands of the lat/long sphere (pole to pole)</source>
        <translation>bandas de latitud de la esfera de longitud/latitud (de polo a polo)</translation>
    </message>
    <message>
        <source>rest radius of the inner layer (must be below radius_outer)</source>
        <translation>radio en reposo de la capa interior (debe ser menor que radius_outer)</translation>
    </message>
    <message>
        <source>rest radius of the outer layer</source>
        <translation>radio en reposo de la capa exterior</translation>
    </message>
    <message>
        <source>rest length of the 1D spring</source>
        <translation>longitud en reposo del resorte 1D</translation>
    </message>
    <message>
        <source>distance between the two particles at the start (the spring hangs along -y)</source>
        <translation>distancia entre las dos partículas al inicio (el resorte cuelga a lo largo de -y)</translation>
    </message>
    <message>
        <source>1: the top particle is fixed in space (thesis fig. 7); 0: both particles move</source>
        <translation>1: la partícula de arriba está fija en el espacio (tesis, fig. 7); 0: ambas partículas se mueven</translation>
    </message>
    <message>
        <source>amplitude of a seeded random displacement of the start positions (breaks symmetry)</source>
        <translation>amplitud de un desplazamiento aleatorio con semilla de las posiciones iniciales (rompe la simetría)</translation>
    </message>
    <message>
        <source>seed of the start perturbation</source>
        <translation>semilla de la perturbación inicial</translation>
    </message>
    <message>
        <source>1D: two masses on one spring hanging along -y, the top one fixed (thesis fig. 7)</source>
        <translation>1D: dos masas en un resorte colgado a lo largo de -y, la de arriba fija (tesis, fig. 7)</translation>
    </message>
    <message>
        <source>2D: two concentric gas-filled rings joined by radius and shear springs (thesis 3.4)</source>
        <translation>2D: dos anillos concéntricos llenos de gas unidos por resortes radiales y de cizalla (tesis 3.4)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled spheres, subdivided octahedron (thesis 3.5.2)</source>
        <translation>3D: dos esferas concéntricas llenas de gas, octaedro subdividido (tesis 3.5.2)</translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled lat/long spheres, the non-uniform sphere (thesis 3.5.1)</source>
        <translation>3D: dos esferas concéntricas llenas de gas de longitud/latitud, la esfera no uniforme (tesis 3.5.1)</translation>
    </message>
    <message>
        <source>explicit Euler: x and v both from the old state (thesis eq. 22)</source>
        <translation>Euler explícito: x y v ambos a partir del estado anterior (tesis, ec. 22)</translation>
    </message>
    <message>
        <source>the thesis&apos;s midpoint (eq. 31-33), i.e. Heun&apos;s RK2: two force evaluations</source>
        <translation>el punto medio de la tesis (ec. 31-33), es decir, el RK2 de Heun: dos evaluaciones de fuerza</translation>
    </message>
    <message>
        <source>classical Runge-Kutta 4 (eq. 35-40): four force evaluations</source>
        <translation>Runge-Kutta 4 clásico (ec. 35-40): cuatro evaluaciones de fuerza</translation>
    </message>
    <message>
        <source>semi-implicit Euler: v from the old forces, then x from the new v</source>
        <translation>Euler semiimplícito: v a partir de las fuerzas anteriores, luego x a partir de la nueva v</translation>
    </message>
    <message>
        <source>velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)</source>
        <translation>Verlet de velocidades (orden 1 con amortiguamiento: el amortiguamiento se toma con la velocidad del medio paso)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 4th-order composition of velocity Verlet: 3 substeps (one backwards), 4 force evaluations (order 1 with damping)</source>
        <translation>composición de cuarto orden de Yoshida a partir de Verlet de velocidades: 3 subpasos (uno hacia atrás), 4 evaluaciones de fuerza (orden 1 con amortiguamiento)</translation>
    </message>
    <message>
        <source>Yoshida&apos;s 8th-order composition of velocity Verlet (solution D): 15 substeps, 16 force evaluations (order 1 with damping)</source>
        <translation>composición de octavo orden de Yoshida a partir de Verlet de velocidades (solución D): 15 subpasos, 16 evaluaciones de fuerza (orden 1 con amortiguamiento)</translation>
    </message>
    <message>
        <source>Dormand-Prince 5(4): adaptive step from atol/rtol, embedded error estimate every step</source>
        <translation>Dormand-Prince 5(4): paso adaptativo a partir de atol/rtol, estimación del error embebida en cada paso</translation>
    </message>
    <message>
        <source>linearised backward Euler (Baraff-Witkin 1998): spring and gas Jacobians, matrix-free CG</source>
        <translation>Euler implícito linealizado (Baraff-Witkin 1998): jacobianos de resortes y gas, gradiente conjugado sin matriz</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order BDF 1-5: Newton, matrix-free GMRES on the analytic Jacobian, implicit-euler&apos;s solve as preconditioner; adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, BDF de orden variable 1-5: Newton, GMRES sin matriz sobre el jacobiano analítico, la resolución de implicit-euler como precondicionador; adaptativo a partir de atol/rtol</translation>
    </message>
    <message>
        <source>extended position-based dynamics (Macklin et al. 2016, small steps 2019): springs as compliant distance constraints, `substeps` substeps of one iteration per step</source>
        <translation>dinámica basada en posiciones extendida (Macklin et al. 2016, pasos pequeños 2019): resortes como restricciones de distancia flexibles, `substeps` subpasos de una iteración por paso</translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order Adams-Moulton 1-12 with fixed-point iteration (non-stiff); adaptive from atol/rtol</source>
        <translation>SUNDIALS CVODE, Adams-Moulton de orden variable 1-12 con iteración de punto fijo (no rígido); adaptativo a partir de atol/rtol</translation>
    </message>
</context>
</TS>
