<?xml version="1.0" encoding="utf-8"?>
<!DOCTYPE TS>
<TS version="2.1" language="ar">
<context>
    <name>FailureText</name>
    <message>
        <source>the inner layer</source>
        <translation>الطبقة الداخلية</translation>
    </message>
    <message>
        <source>the outer layer</source>
        <translation>الطبقة الخارجية</translation>
    </message>
    <message>
        <source>the layer</source>
        <translation>الطبقة</translation>
    </message>
    <message>
        <source>%1 turned inside out (its area is %2, rest %3)</source>
        <translation>%1 انقلبت على نفسها (مساحتها %2، وفي السكون %3)</translation>
    </message>
    <message>
        <source>%1 turned inside out (its volume is %2, rest %3)</source>
        <translation>%1 انقلبت على نفسها (حجمها %2، وفي السكون %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its area is %2, rest %3)</source>
        <translation>%1 انهارت (مساحتها %2، وفي السكون %3)</translation>
    </message>
    <message>
        <source>%1 collapsed (its volume is %2, rest %3)</source>
        <translation>%1 انهارت (حجمها %2، وفي السكون %3)</translation>
    </message>
    <message>
        <source>body %1: %2</source>
        <translation>الجسم %1: %2</translation>
    </message>
    <message>
        <source>the state became non-finite (NaN or infinity): the step is far too large for these forces</source>
        <translation>لم تعد الحالة منتهية (NaN أو لانهاية): الخطوة أكبر بكثير مما تحتمله هذه القوى</translation>
    </message>
    <message>
        <source>rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too stiff or singular)</source>
        <translation>rk45: صارت الخطوة أصغر من أدنى خطوة؛ لا يمكن بلوغ التفاوت المسموح (النظام شديد الصلابة أو شاذ)</translation>
    </message>
    <message>
        <source>implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is not positive definite at this step (the body is too deformed or the step too large)</source>
        <translation>implicit-euler: لم يتقارب الحل الخطي (التدرج المترافق)؛ النظام المُخطَّط ليس موجب التعريف في هذه الخطوة (الجسم مشوَّه أكثر من اللازم أو الخطوة كبيرة جدًا)</translation>
    </message>
    <message>
        <source>runaway velocity: a particle moves %1 m/s, farther than the whole box in one step</source>
        <translation>سرعة جامحة: جسيم يتحرك بسرعة %1 م/ث، أبعد من الصندوق كله في خطوة واحدة</translation>
    </message>
    <message>
        <source>runaway energy: kinetic + elastic energy %1 J exceeds %2 J (%3 × the body&apos;s energy scale)</source>
        <translation>طاقة جامحة: الطاقة الحركية + المرنة %1 J تتجاوز %2 J (%3 × مقياس طاقة الجسم)</translation>
    </message>
    <message>
        <source>the state is no longer finite (particle %1)</source>
        <translation>لم تعد الحالة منتهية (الجسيم %1)</translation>
    </message>
    <message>
        <source>particle %1 reached a wall: the float path has no contact (use precision double)</source>
        <translation>بلغ الجسيم %1 جدارًا: حساب float بلا تلامس (اختر الدقة double)</translation>
    </message>
    <message>
        <source>body %1&apos;s outer layer passed through itself in a step of %2 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>عبرت الطبقة الخارجية للجسم %1 نفسها في خطوة مدتها %2 s: الخطوة أكبر من أن تحتمل هذا الاصطدام (dt أصغر، أو مُكامِل متكيّف يقسم مثل هذه الخطوة على اثنين)</translation>
    </message>
    <message>
        <source>bodies %1 and %2 intersect (their outer layers crossed) in a step of %3 s: the step is too large for this impact (a smaller dt, or an adaptive integrator, which halves such a step)</source>
        <translation>تداخل الجسمان %1 و%2 (تقاطعت طبقتاهما الخارجيتان) في خطوة مدتها %3 s: الخطوة أكبر من أن تحتمل هذا الاصطدام (dt أصغر، أو مُكامِل متكيّف يقسم مثل هذه الخطوة على اثنين)</translation>
    </message>
    <message>
        <source>exact spectrum, %1 eigenvalues</source>
        <translation>الطيف الدقيق، %1 قيمة ذاتية</translation>
    </message>
    <message>
        <source>Arnoldi, %1 Ritz values of %2</source>
        <translation>أرنولدي، %1 قيمة ريتز من %2</translation>
    </message>
    <message>
        <source>exact step matrix</source>
        <translation>مصفوفة الخطوة الدقيقة</translation>
    </message>
    <message>
        <source>modes of M^-1 K</source>
        <translation>أنماط M^-1 K</translation>
    </message>
    <message>
        <source>%1 chooses its own step: no DT limit from stability</source>
        <translation>%1 يختار خطوته بنفسه: لا حدّ على DT من الاستقرار</translation>
    </message>
    <message>
        <source>%1 is stable at every DT on this body</source>
        <translation>%1 مستقر عند كل DT على هذا الجسم</translation>
    </message>
    <message>
        <source>%1 has no stable DT on this body: its undamped modes grow for every DT (%2)</source>
        <translation>لا DT مستقرًا لـ %1 على هذا الجسم: أنماطه غير المخمَّدة تنمو عند كل DT (%2)</translation>
    </message>
    <message>
        <source>%1 is stable up to DT = %2 s on this body (%3)</source>
        <translation>%1 مستقر حتى DT = %2 s على هذا الجسم (%3)</translation>
    </message>
    <message>
        <source>%1 has no stable step on this body&apos;s undamped modes (highest w = %2 rad/s): its energy grows for every dt, here by ~%3 per second; use dt &lt;= %4 s (growth below 1 per second) or another method</source>
        <translation>لا خطوة مستقرة لـ %1 على أنماط هذا الجسم غير المخمَّدة (أعلى w = %2 rad/s): طاقته تنمو عند كل dt، هنا بنحو %3 في الثانية؛ استخدم dt &lt;= %4 s (نمو دون 1 في الثانية) أو طريقة أخرى</translation>
    </message>
    <message>
        <source>dt = %1 s is above %2&apos;s largest stable step on this body, %3 s (linearised: %4; fastest |lambda| = %5 1/s); it will likely blow up (implicit-euler or rk45 will not)</source>
        <translation>dt = %1 s أكبر من أكبر خطوة مستقرة لـ %2 على هذا الجسم، %3 s (خطيًا: %4؛ أسرع |lambda| = %5 1/s)؛ سينفجر الحساب على الأرجح (implicit-euler أو rk45 لا)</translation>
    </message>
</context>
<context>
    <name>QObject</name>
    <message>
        <source>solid</source>
        <translation>متصل</translation>
    </message>
    <message>
        <source>hatched</source>
        <translation>مخطط</translation>
    </message>
    <message>
        <source>dotted</source>
        <translation>منقط</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>تعذر فتح %1: %2</translation>
    </message>
    <message>
        <source>Could not write %1: %2</source>
        <translation>تعذرت كتابة %1: %2</translation>
    </message>
    <message>
        <source>the data was not written completely</source>
        <translation>لم تُكتب البيانات كاملة</translation>
    </message>
    <message>
        <source>Could not encode %1 as %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No plot to export</source>
        <translation>لا يوجد رسم بياني للتصدير</translation>
    </message>
    <message>
        <source>Could not encode %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Three Verlet substeps (the middle one backwards): fourth order, and energy stays bounded like Verlet&apos;s; stable up to h·ω ≈ 1.57 on an undamped spring.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fifteen Verlet substeps: eighth order for undamped bodies, the error reaches round-off at moderate steps; 16 force evaluations a step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Chooses its own step to meet a tolerance; the readout shows its error estimate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stable at any DT (it damps instead of blowing up): the one to use for DT 0.3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A production stiff solver (SUNDIALS): wins where stiffness is damping (overdamped springs), not where it is fast oscillation, which it must still follow.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>A production non-stiff solver (SUNDIALS): high order, few force evaluations per step.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The game-physics way (Jolt, PhysX): stable at DT 1/60 on stiff springs, but it removes energy the body never lost; more substeps, less loss.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h2&gt;Elastic Lab&lt;/h2&gt;&lt;p&gt;A two-layer elastic body: particles joined by springs, with gas inside each closed layer. Drag the body with the mouse; change any parameter while it runs.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;The model&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;&lt;b&gt;Particles&lt;/b&gt; carry mass; gravity pulls along −y.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Springs&lt;/b&gt; (Hooke + damping): &lt;i&gt;structural&lt;/i&gt; springs along each layer (KS, KD), &lt;i&gt;radius&lt;/i&gt; springs between paired inner and outer particles and &lt;i&gt;shear&lt;/i&gt; springs across them (RKS, RKD).&lt;/li&gt;&lt;li&gt;&lt;b&gt;Gas&lt;/b&gt;: each closed layer encloses gas with P = nRT / V, pushing outward on every edge (2D) or face (3D). V is the exact area or volume.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Mouse spring&lt;/b&gt; (MKS, MKD) from the pointer to the grabbed particle.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Contact&lt;/b&gt; is a smooth force inside the equations of motion: a particle that sinks a depth d into a wall is pushed back by k d³ (contact energy k d⁴/4), damped so that one hitting at contact_speed rebounds with the restitution e, with smooth Coulomb friction, and a barrier of the same kind keeps the inner layer inside the outer one. contact = projection restores the thesis program instead, which puts a particle back and reverses its normal speed after each step.&lt;/li&gt;&lt;li&gt;&lt;b&gt;Resolution&lt;/b&gt; (Scene dock): with scaling = physical the masses and spring constants hold at the scene&apos;s default mesh, and a finer mesh keeps the body&apos;s totals (layer mass, material stiffness), so it is the same body, only finer; scaling = thesis makes them per particle and per spring at every mesh. A finer body has faster modes and needs a smaller DT: the window offers one when a rebuild needs it.&lt;/li&gt;&lt;/ul&gt;&lt;p&gt;The plots show the energy book: kinetic + spring + gravity + gas + contact is the total; what damping and contact take out is &apos;removed&apos;. For an exact integrator, total + removed − work by the mouse stays constant; the readout&apos;s &lt;i&gt;energy drift&lt;/i&gt; is how far it is off.&lt;/p&gt;&lt;p&gt;View → &lt;b&gt;Energy bars&lt;/b&gt; shows the same book as bars, one per term, in the plot&apos;s colours, with the drift last. View → &lt;b&gt;P–V diagram&lt;/b&gt; shows each gas layer&apos;s pressure against its volume: the trail lies on the isotherm P = nRT / V, drawn dashed.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Integrators&lt;/h3&gt;&lt;table border=1 cellspacing=0 cellpadding=4&gt;&lt;tr&gt;&lt;th&gt;name&lt;/th&gt;&lt;th&gt;order&lt;/th&gt;&lt;th&gt;what it does&lt;/th&gt;&lt;th&gt;in class&lt;/th&gt;&lt;/tr&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Presets&lt;/h3&gt;&lt;ul&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;Mouse&lt;/h3&gt;&lt;ul&gt;&lt;li&gt;Left-drag on the body: grab the nearest outer particle and pull it.&lt;/li&gt;&lt;li&gt;Left-drag elsewhere, or Shift+left-drag (3D): orbit. Right- or middle-drag: pan. Wheel: zoom. View → Reset view.&lt;/li&gt;&lt;/ul&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;h3&gt;More&lt;/h3&gt;&lt;ul&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The GUI (docs/gui.md)</source>
        <translation>الواجهة (docs/gui.md)</translation>
    </message>
    <message>
        <source>Architecture (docs/architecture.md)</source>
        <translation>البنية (docs/architecture.md)</translation>
    </message>
    <message>
        <source>README</source>
        <translation>README</translation>
    </message>
    <message>
        <source>1. How large may DT be for Euler?</source>
        <translation>1. ما أكبر DT مسموح لطريقة أويلر؟</translation>
    </message>
    <message>
        <source>2. Energy drift: Euler, midpoint, RK4</source>
        <translation>2. انجراف الطاقة: أويلر، النقطة الوسطى، RK4</translation>
    </message>
    <message>
        <source>3. A heavy inner layer: liquid motion</source>
        <translation>3. طبقة داخلية ثقيلة: حركة السائل</translation>
    </message>
    <message>
        <source>4. A finer sphere needs a smaller DT</source>
        <translation>4. الكرة الأدق تحتاج DT أصغر</translation>
    </message>
    <message>
        <source>5. Pressure and volume on the isotherm</source>
        <translation>5. الضغط والحجم على منحنى ثبوت الحرارة</translation>
    </message>
    <message>
        <source>6. Restitution: a particle and a body</source>
        <translation>6. معامل الارتداد: جسيم وجسم</translation>
    </message>
    <message>
        <source>7. Stiff springs: explicit against implicit</source>
        <translation>7. نوابض صلبة: صريح مقابل ضمني</translation>
    </message>
    <message>
        <source>8. Why symplectic? Energy over ten thousand periods</source>
        <translation>8. لماذا التماثل السمبلكتي؟ الطاقة عبر عشرة آلاف دورة</translation>
    </message>
    <message>
        <source>Goal</source>
        <translation>الهدف</translation>
    </message>
    <message>
        <source>What to do</source>
        <translation>ما يجب فعله</translation>
    </message>
    <message>
        <source>What to look at</source>
        <translation>ما يجب ملاحظته</translation>
    </message>
    <message>
        <source>The measured answer</source>
        <translation>الإجابة المقيسة</translation>
    </message>
    <message>
        <source>Why</source>
        <translation>لماذا</translation>
    </message>
    <message>
        <source>Springs</source>
        <translation>النوابض</translation>
    </message>
    <message>
        <source>Gas</source>
        <translation>الغاز</translation>
    </message>
    <message>
        <source>Mass</source>
        <translation>الكتلة</translation>
    </message>
    <message>
        <source>Environment</source>
        <translation>البيئة</translation>
    </message>
    <message>
        <source>Contact</source>
        <translation>التلامس</translation>
    </message>
    <message>
        <source>Mouse spring</source>
        <translation>نابض الفأرة</translation>
    </message>
    <message>
        <source>Time</source>
        <translation>الزمن</translation>
    </message>
    <message>
        <source>Shape</source>
        <translation>الشكل</translation>
    </message>
    <message>
        <source>Start</source>
        <translation>ابدأ</translation>
    </message>
    <message>
        <source>gas nRT</source>
        <translation>الغاز nRT</translation>
    </message>
    <message>
        <source>gas nRT inner</source>
        <translation>الغاز nRT الداخلي</translation>
    </message>
    <message>
        <source>gas nRT outer</source>
        <translation>الغاز nRT الخارجي</translation>
    </message>
    <message>
        <source>Area per layer</source>
        <translation>المساحة لكل طبقة</translation>
    </message>
    <message>
        <source>Volume per layer</source>
        <translation>الحجم لكل طبقة</translation>
    </message>
    <message>
        <source>area [m²]</source>
        <translation>المساحة [m²]</translation>
    </message>
    <message>
        <source>volume [m³]</source>
        <translation>الحجم [m³]</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>داخلية</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>خارجية</translation>
    </message>
    <message>
        <source>Pressure per layer</source>
        <translation>الضغط لكل طبقة</translation>
    </message>
    <message>
        <source>pressure [N/m]</source>
        <translation>الضغط [N/m]</translation>
    </message>
    <message>
        <source>pressure [Pa]</source>
        <translation>الضغط [Pa]</translation>
    </message>
    <message>
        <source>Energy</source>
        <translation>الطاقة</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>الطاقة [J]</translation>
    </message>
    <message>
        <source>kinetic</source>
        <translation>حركية</translation>
    </message>
    <message>
        <source>spring</source>
        <translation>نابض</translation>
    </message>
    <message>
        <source>gravity</source>
        <translation>جاذبية</translation>
    </message>
    <message>
        <source>gas</source>
        <translation>غاز</translation>
    </message>
    <message>
        <source>contact</source>
        <translation>تلامس</translation>
    </message>
    <message>
        <source>total</source>
        <translation>الكلية</translation>
    </message>
    <message>
        <source>removed</source>
        <translation>مُزالة</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>أزالها التلامس</translation>
    </message>
    <message>
        <source>spring: structural</source>
        <translation>نابض: بنيوي</translation>
    </message>
    <message>
        <source>spring: radius</source>
        <translation>نابض: نصف قطري</translation>
    </message>
    <message>
        <source>spring: shear</source>
        <translation>نابض: قص</translation>
    </message>
    <message>
        <source>mouse spring</source>
        <translation>نابض الفأرة</translation>
    </message>
    <message>
        <source>removed by damping</source>
        <translation>أزالها التخميد</translation>
    </message>
    <message>
        <source>removed by projection</source>
        <translation>أزالها الإسقاط</translation>
    </message>
    <message>
        <source>drift (balance error)</source>
        <translation>الانجراف (خطأ الميزان)</translation>
    </message>
    <message>
        <source>1D drop: two masses on a spring</source>
        <translation>سقوط أحادي البعد: كتلتان على نابض</translation>
    </message>
    <message>
        <source>Both masses fall, hit the floor and bounce; the spring oscillates (thesis fig. 7).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1D hanging spring</source>
        <translation>نابض معلق أحادي البعد</translation>
    </message>
    <message>
        <source>The top mass is fixed; the lower one oscillates around the stretched rest length.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2D ring</source>
        <translation>حلقة ثنائية الأبعاد</translation>
    </message>
    <message>
        <source>Two gas-filled rings joined by radius and shear springs drop onto the floor (thesis 3.4).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D sphere</source>
        <translation>كرة ثلاثية الأبعاد</translation>
    </message>
    <message>
        <source>Two gas-filled spheres (subdivided octahedron) drop and bounce (thesis 3.5.2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D lat/long sphere (non-uniform)</source>
        <translation>كرة ثلاثية الأبعاد بخطوط الطول والعرض (غير منتظمة)</translation>
    </message>
    <message>
        <source>The lat/long sphere: particles crowd at the poles, so the body is not uniform (thesis 3.5.1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Heavy inner layer (non-uniform density)</source>
        <translation>طبقة داخلية ثقيلة (كثافة غير منتظمة)</translation>
    </message>
    <message>
        <source>The inner layer is five times heavier: it sinks inside the outer one and the body lands bottom-heavy (thesis 8.1).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Liquid motion and inertia</source>
        <translation>حركة السائل والقصور الذاتي</translation>
    </message>
    <message>
        <source>Inner and outer layers pushed in opposite directions (3 m/s), without gravity and with soft, lightly damped radius and shear springs: the inner layer sloshes inside the outer one like a liquid (thesis fig. 47).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stability experiment, DT = %1 s</source>
        <translation>تجربة الاستقرار، DT = %1 s</translation>
    </message>
    <message>
        <source>Euler, midpoint and RK4 from the same start at DT = %1 s (thesis 7.2.2, figs. 41-43). Watch which one blows up.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>غير محدود</translation>
    </message>
    <message>
        <source>none</source>
        <translation>لا شيء</translation>
    </message>
    <message>
        <source>Cheapest and least stable: on an undamped spring it gains energy at every DT. On the two-layer ring it holds for 2 s up to DT %1 s (measured).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Two force evaluations per step, second order; on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Four evaluations, fourth order; stable up to h·ω ≈ 2.8: on the two-layer ring it holds for 2 s up to DT %1 s (measured), so it fails at the thesis&apos;s 0.03 and 0.3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Same cost as Euler, but energy stays bounded on an undamped spring (h·ω &amp;lt; 2).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Velocity Verlet: time-reversible, good long-run energy behaviour. Second order without damping; with the dampers on (every scene here) its damping sees the half-step velocity and it is first order: the fitted order on the damped spring is %1 (measured).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2 (1 damped)</source>
        <translation>2 (1 مع التخميد)</translation>
    </message>
    <message>
        <source>&lt;p&gt;&lt;b&gt;Lessons&lt;/b&gt; menu (or Help → Experiments): %1 guided experiments, each set up in one click, with what to change, what to look at and the answer measured with elastic-lab-cli; the Lesson dock shows what each answer expects beside what your run gives.&lt;/p&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Lessons &gt; Lesson texts explains what to do.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>height of particle %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>speed of particle %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>height of the inner layer&apos;s centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>height of the outer layer&apos;s centre</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre-of-mass height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre-of-mass speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>layers&apos; separation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>9. Two balloons collide: momentum and energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>10. A soft stack: how the bottom body carries the others</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>WorldExport</name>
    <message>
        <source>No run of several bodies to export</source>
        <translation>لا يوجد تشغيل لعدة أجسام لتصديره</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>تصدير البيانات</translation>
    </message>
    <message>
        <source>CSV of several bodies, comma and decimal point (*.csv)</source>
        <translation>CSV لعدة أجسام، فاصلة ونقطة عشرية (*.csv)</translation>
    </message>
    <message>
        <source>Wrote %1 rows of the world to %2</source>
        <translation>كُتب %1 صفًا من العالم إلى %2</translation>
    </message>
</context>
<context>
    <name>elui::BodiesDock</name>
    <message>
        <source>Bodies</source>
        <translation>الأجسام</translation>
    </message>
    <message>
        <source>The bodies of the scene, total momentum and the smallest gap, with their curves against simulated time</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This dock is for scenes of several bodies: Presets &gt; Several bodies, or a scene file of several bodies.</source>
        <translation>هذه اللوحة لمشاهد الأجسام المتعددة: إعدادات مسبقة &gt; أجسام متعددة، أو ملف مشهد لعدة أجسام.</translation>
    </message>
    <message>
        <source>body</source>
        <translation>الجسم</translation>
    </message>
    <message>
        <source>mass [kg]</source>
        <translation>الكتلة [kg]</translation>
    </message>
    <message>
        <source>centre [m]</source>
        <translation>المركز [m]</translation>
    </message>
    <message>
        <source>velocity [m/s]</source>
        <translation>السرعة [m/s]</translation>
    </message>
    <message>
        <source>volume in/out</source>
        <translation>الحجم داخلي/خارجي</translation>
    </message>
    <message>
        <source>pressure in/out</source>
        <translation>الضغط داخلي/خارجي</translation>
    </message>
    <message>
        <source>Total momentum</source>
        <translation>كمية الحركة الكلية</translation>
    </message>
    <message>
        <source>min_gap</source>
        <translation>min_gap</translation>
    </message>
    <message>
        <source>Volume per body and layer</source>
        <translation>الحجم لكل جسم وطبقة</translation>
    </message>
    <message>
        <source>Pressure per body and layer</source>
        <translation>الضغط لكل جسم وطبقة</translation>
    </message>
    <message>
        <source>gap [m]</source>
        <translation>الفجوة [m]</translation>
    </message>
    <message>
        <source>volume</source>
        <translation>الحجم</translation>
    </message>
    <message>
        <source>pressure</source>
        <translation>الضغط</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>ring2d: particles per layer; sphere3d: subdivisions; sphere3d-latlong: slices</source>
        <translation>ring2d: الجسيمات في كل طبقة؛ sphere3d: التقسيمات؛ sphere3d-latlong: الشرائح</translation>
    </message>
    <message>
        <source>kind, level</source>
        <translation>النوع، المستوى</translation>
    </message>
    <message>
        <source>where [m]</source>
        <translation>الموضع [m]</translation>
    </message>
    <message>
        <source>how fast [m/s]</source>
        <translation>مدى السرعة [m/s]</translation>
    </message>
    <message>
        <source>Add body</source>
        <translation>إضافة جسم</translation>
    </message>
    <message>
        <source>Remove selected</source>
        <translation>إزالة المحدد</translation>
    </message>
    <message>
        <source>inner</source>
        <translation>داخلية</translation>
    </message>
    <message>
        <source>outer</source>
        <translation>خارجية</translation>
    </message>
    <message>
        <source> (body%1 with itself)</source>
        <translation> (الجسم%1 مع نفسه)</translation>
    </message>
    <message>
        <source> (body%1 and body%2)</source>
        <translation> (الجسم%1 والجسم%2)</translation>
    </message>
    <message>
        <source>beyond %1 m (nothing that close)</source>
        <translation>أبعد من %1 m (لا شيء بهذا القرب)</translation>
    </message>
    <message>
        <source>&lt;b&gt;momentum&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;angular momentum&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;contact between bodies&lt;/b&gt; %4 J, %5 pairs in the skin</source>
        <translation>&lt;b&gt;كمية الحركة&lt;/b&gt; %1 kg m/s&lt;br&gt;&lt;b&gt;الزخم الزاوي&lt;/b&gt; %2 kg m²/s&lt;br&gt;&lt;b&gt;min_gap&lt;/b&gt; %3&lt;br&gt;&lt;b&gt;التلامس بين الأجسام&lt;/b&gt; %4 J، %5 أزواج في القشرة</translation>
    </message>
    <message>
        <source>%1: not a number</source>
        <translation>%1: ليس عددًا</translation>
    </message>
    <message>
        <source>Choose a body in the list first.</source>
        <translation>اختر جسمًا من القائمة أولًا.</translation>
    </message>
    <message>
        <source>A world keeps at least one body.</source>
        <translation>يبقى في العالم جسم واحد على الأقل.</translation>
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
        <translation>جنبًا إلى جنب</translation>
    </message>
    <message>
        <source>Run the same scene with up to three integrators from the same start state. Parameter edits and mouse drags go to all of them.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>(none)</source>
        <translation>(لا شيء)</translation>
    </message>
    <message>
        <source>View %1</source>
        <translation>العرض %1</translation>
    </message>
    <message>
        <source>The integrator of the first view</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The integrator of this view, or none</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 s, common to every view (set it in the Run dock)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT</source>
        <translation>DT</translation>
    </message>
    <message>
        <source>Start the views side by side from the current start state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep the views as they are</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::ConservationDialog</name>
    <message>
        <source>Long-time energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run length in periods of the body&apos;s fastest mode (damping switched off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The fixed step of every run [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>float: the float build of the 1D spring, where round-off shows as a random walk</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Periods</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Precision</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|energy error| envelope [J]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>α</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>95 % interval</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>class</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>final |ΔE| [J]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>relative</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>steps</source>
        <translation>الخطوات</translation>
    </message>
    <message>
        <source>status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: %2, α = %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: failed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slope 1/2 (random walk)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slope 1 (drift)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The study did not run: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Undamped (%1). Fastest mode ω = %2 rad/s, period %3 s; DT = %4 s (h·ω = %5); %6 periods = %7 s. α: slope of log |ΔE| against log t from 10 periods on; bounded &lt; 0.25 ≤ random walk &lt; 0.75 ≤ drift.</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::EnergyBarsDock</name>
    <message>
        <source>Energy bars</source>
        <translation>أعمدة الطاقة</translation>
    </message>
    <message>
        <source>Each part of the energy as a bar, named on the axis; the values are in the Run dock&apos;s readout</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Energy book</source>
        <translation>ميزان الطاقة</translation>
    </message>
    <message>
        <source>energy [J]</source>
        <translation>الطاقة [J]</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
total %2, at the start %3</source>
        <translation>الطاقة عند t = %1 s
الكلية %2، في البداية %3</translation>
    </message>
    <message>
        <source>Energy at t = %1 s
%2</source>
        <translation>الطاقة عند t = %1 s
%2</translation>
    </message>
</context>
<context>
    <name>elui::FailureBanner</name>
    <message>
        <source>Start again from the beginning with the step that ran through the failed stretch</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use implicit-euler and reset</source>
        <translation>استخدم implicit-euler وأعد الضبط</translation>
    </message>
    <message>
        <source>Start again with the implicit Euler integrator, which is stable at any time step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>إعادة الضبط</translation>
    </message>
    <message>
        <source>Start again from the beginning with the same settings</source>
        <translation>ابدأ من جديد من البداية بالإعدادات نفسها</translation>
    </message>
    <message>
        <source>&lt;b&gt;The simulation blew up&lt;/b&gt; at t = %1 s (step %2): %3. The run is paused and shows the last good state.</source>
        <translation>&lt;b&gt;انفجرت المحاكاة&lt;/b&gt; عند t = %1 s (الخطوة %2): %3. التشغيل متوقف مؤقتًا ويعرض آخر حالة سليمة.</translation>
    </message>
    <message>
        <source>Checking whether a smaller step survives the same stretch (a re-run at a quarter of DT, in the background)…</source>
        <translation>يجري التحقق مما إذا كانت خطوة أصغر تجتاز المقطع نفسه (إعادة تشغيل بربع DT، في الخلفية)…</translation>
    </message>
    <message>
        <source>Try a smaller DT, a more stable integrator (rk4, or implicit-euler), softer springs or less pressure, then Reset.</source>
        <translation>جرّب DT أصغر، أو مكاملًا أكثر استقرارًا (rk4 أو implicit-euler)، أو نوابض ألين أو ضغطًا أقل، ثم أعد الضبط.</translation>
    </message>
    <message>
        <source>Use DT = %1 s and reset</source>
        <translation>استخدم DT = %1 s وأعد الضبط</translation>
    </message>
    <message>
        <source>The body itself collapses — no step size will save it: run again from t = %1 s at a step of %2 s (%3), it fails at t = %4 s as well (%5). Change the body instead: lighter masses or less gravity, stiffer springs (ks, and the radial ones), more gas pressure, or more damping.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The step was too large: run again from t = %1 s at a step of %2 s, the same stretch runs through t = %3 s. The linearised body agrees: %4.</source>
        <translation>كانت الخطوة كبيرة جدًا: بإعادة التشغيل من t = %1 s بخطوة %2 s يجتاز المقطع نفسه حتى t = %3 s. ويؤكد الجسم الخطي ذلك: %4.</translation>
    </message>
</context>
<context>
    <name>elui::HelpDialog</name>
    <message>
        <source>Elastic Lab help</source>
        <translation>مساعدة Elastic Lab</translation>
    </message>
    <message>
        <source>Help</source>
        <translation>المساعدة</translation>
    </message>
    <message>
        <source>How to use Elastic Lab: the view, the docks, the integrators and the files</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the help</source>
        <translation>أغلق المساعدة</translation>
    </message>
</context>
<context>
    <name>elui::LessonDock</name>
    <message>
        <source>Lesson</source>
        <translation>الدرس</translation>
    </message>
    <message>
        <source>Run until t =</source>
        <translation>شغّل حتى t =</translation>
    </message>
    <message>
        <source>Run as fast as possible and pause at this simulated time.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time between Start and Stop (the first view&apos;s clock).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start</source>
        <translation>ابدأ</translation>
    </message>
    <message>
        <source>Zero</source>
        <translation>صفر</translation>
    </message>
    <message>
        <source>answer</source>
        <translation>الإجابة</translation>
    </message>
    <message>
        <source>expected</source>
        <translation>المتوقع</translation>
    </message>
    <message>
        <source>you got</source>
        <translation>ما حصلت عليه</translation>
    </message>
    <message>
        <source>Measure</source>
        <translation>قِس</translation>
    </message>
    <message>
        <source>Measure every answer on the parameters in use, as the lesson&apos;s elastic-lab-cli commands do (stability scans, weightless impacts, runs).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;small&gt;you got: from your run, or &lt;i&gt;measured&lt;/i&gt; (Measure); green within the text&apos;s tolerance, amber off it&lt;/small&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>No lesson: choose one in the Lessons menu. Run until and the stopwatch work for any scene.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stopwatch: &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Stop</source>
        <translation>أوقف</translation>
    </message>
    <message>
        <source>read off your run</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>press Measure</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured on the parameters in use</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>t = &lt;b&gt;%1 s&lt;/b&gt;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: energy drift &lt;b&gt;%2 J&lt;/b&gt;%3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, blew up at t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre of mass: %1 m above the floor, vertical speed %2 m/s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>layer centres above the floor: inner %1 m, outer %2 m; the inner one sits &lt;b&gt;%3 m&lt;/b&gt; %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>below</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>above</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre of mass hit the floor at %1 m/s%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, left it at %1 m/s (ratio %2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lowest point %1 m above the floor%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>lowest point %1 m into the floor (contact)%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>; last left the floor at t = %1 s</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inner layer: %1 %2, pressure %3 %4</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measuring on the parameters in use…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run until a time, a stopwatch, and each answer of the lesson beside what your run gives</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run until this simulated time</source>
        <translation>شغّل حتى هذا الزمن المحاكى</translation>
    </message>
    <message>
        <source>The simulated time [s] at which Run until pauses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Start or stop the stopwatch on the simulated clock</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set the stopwatch back to zero</source>
        <translation>أعد ساعة الإيقاف إلى الصفر</translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; smallest gap %2 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total momentum &lt;b&gt;%1 kg m/s&lt;/b&gt;; no gap below %2 m</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>body%1: centre velocity %2 m/s, outer %3 %4 of %5 at rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>area</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>volume</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::LessonsDialog</name>
    <message>
        <source>Experiments</source>
        <translation>التجارب</translation>
    </message>
    <message>
        <source>Short guided experiments: each sets up a scene, says what to change and what to look at, and gives the answer measured with elastic-lab-cli.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The guided experiments; the arrow keys choose one, its text is beside the list</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Experiment</source>
        <translation>التجربة</translation>
    </message>
    <message>
        <source>What the chosen experiment sets up, what to change and what to look for</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Set up this experiment</source>
        <translation>جهّز هذه التجربة</translation>
    </message>
    <message>
        <source>Set up the chosen experiment in the main window: its scene, parameters and docks</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Close the experiments; the main window keeps its scene</source>
        <translation type="unfinished"></translation>
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
        <translation>&amp;فتح مشهد...</translation>
    </message>
    <message>
        <source>A scene file (.json): scene, parameters, integrator and, if saved, the exact state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Save scene</source>
        <translation>&amp;حفظ المشهد</translation>
    </message>
    <message>
        <source>Scene, every parameter, the integrator and the exact current state</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save scene &amp;as...</source>
        <translation>حفظ المشهد &amp;باسم...</translation>
    </message>
    <message>
        <source>Export &amp;Data (CSV, Excel)...</source>
        <translation>تصدير ال&amp;بيانات (CSV، Excel)...</translation>
    </message>
    <message>
        <source>The time series of this run, with the same columns as elastic-lab-cli run --csv</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export &amp;plots (PNG, SVG, PDF)...</source>
        <translation>تصدير ال&amp;رسوم (PNG، SVG، PDF)...</translation>
    </message>
    <message>
        <source>Save &amp;viewport screenshot...</source>
        <translation>حفظ &amp;لقطة للعرض...</translation>
    </message>
    <message>
        <source>&amp;Quit</source>
        <translation>&amp;خروج</translation>
    </message>
    <message>
        <source>&amp;Run / Pause</source>
        <translation>&amp;تشغيل / إيقاف مؤقت</translation>
    </message>
    <message>
        <source>&amp;Step</source>
        <translation>&amp;خطوة</translation>
    </message>
    <message>
        <source>R&amp;eset</source>
        <translation>إ&amp;عادة الضبط</translation>
    </message>
    <message>
        <source>Reset &amp;view</source>
        <translation>إعادة ضبط ال&amp;عرض</translation>
    </message>
    <message>
        <source>&amp;Presentation mode</source>
        <translation>وضع ال&amp;عرض التقديمي</translation>
    </message>
    <message>
        <source>Everything %1x larger, with large Run, Step, Back and Reset buttons: for a projector</source>
        <translation>كل شيء أكبر %1 مرة، مع أزرار كبيرة للتشغيل والخطوة والرجوع وإعادة الضبط: لجهاز العرض</translation>
    </message>
    <message>
        <source>&amp;Larger text</source>
        <translation>نص أ&amp;كبر</translation>
    </message>
    <message>
        <source>S&amp;maller text</source>
        <translation>نص أ&amp;صغر</translation>
    </message>
    <message>
        <source>Structural springs</source>
        <translation>النوابض البنيوية</translation>
    </message>
    <message>
        <source>Radius springs</source>
        <translation>النوابض نصف القطرية</translation>
    </message>
    <message>
        <source>Shear springs</source>
        <translation>نوابض القص</translation>
    </message>
    <message>
        <source>Faces</source>
        <translation>الأوجه</translation>
    </message>
    <message>
        <source>Particles</source>
        <translation>الجسيمات</translation>
    </message>
    <message>
        <source>Normals</source>
        <translation>العموديات</translation>
    </message>
    <message>
        <source>Force vectors</source>
        <translation>متجهات القوة</translation>
    </message>
    <message>
        <source>Colour springs by strain</source>
        <translation>تلوين النوابض حسب الانفعال</translation>
    </message>
    <message>
        <source>Collision box</source>
        <translation>صندوق التصادم</translation>
    </message>
    <message>
        <source>&amp;Side by side...</source>
        <translation>&amp;جنبًا إلى جنب...</translation>
    </message>
    <message>
        <source>Single &amp;view</source>
        <translation>عرض &amp;واحد</translation>
    </message>
    <message>
        <source>Elastic Lab &amp;help</source>
        <translation>&amp;مساعدة Elastic Lab</translation>
    </message>
    <message>
        <source>Guided experiments: a scene set up in one click, what to change, what to look at, the measured answer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;About</source>
        <translation>&amp;حول</translation>
    </message>
    <message>
        <source>About Elastic Lab</source>
        <translation>حول Elastic Lab</translation>
    </message>
    <message>
        <source>Elastic Lab: the dynamics of two-layer elastic bodies, for teaching.</source>
        <translation>Elastic Lab: ديناميكا الأجسام المرنة ذات الطبقتين، للتعليم.</translation>
    </message>
    <message>
        <source>&amp;File</source>
        <translation>&amp;ملف</translation>
    </message>
    <message>
        <source>Open &amp;recent</source>
        <translation>فُتح &amp;مؤخرًا</translation>
    </message>
    <message>
        <source>&amp;Simulation</source>
        <translation>&amp;محاكاة</translation>
    </message>
    <message>
        <source>&amp;View</source>
        <translation>&amp;عرض</translation>
    </message>
    <message>
        <source>&amp;High contrast</source>
        <translation>تباين &amp;عالٍ</translation>
    </message>
    <message>
        <source>White text on black, yellow highlight and focus: for low vision and projectors</source>
        <translation>نص أبيض على أسود، وإبراز وتركيز أصفران: لضعف البصر ولأجهزة العرض</translation>
    </message>
    <message>
        <source>&amp;Compare</source>
        <translation>&amp;مقارنة</translation>
    </message>
    <message>
        <source>&amp;Presets</source>
        <translation>إعدادات &amp;مسبقة</translation>
    </message>
    <message>
        <source>S&amp;tudies</source>
        <translation>&amp;دراسات</translation>
    </message>
    <message>
        <source>&amp;Work-precision study...</source>
        <translation>دراسة ال&amp;جهد والدقة...</translation>
    </message>
    <message>
        <source>&amp;Refinement study...</source>
        <translation>دراسة ال&amp;تنعيم...</translation>
    </message>
    <message>
        <source>&amp;Stability scan...</source>
        <translation>مسح الا&amp;ستقرار...</translation>
    </message>
    <message>
        <source>&amp;Long-time energy...</source>
        <translation>الطاقة على المدى ال&amp;طويل...</translation>
    </message>
    <message>
        <source>&amp;Help</source>
        <translation>م&amp;ساعدة</translation>
    </message>
    <message>
        <source>DT set to %1 s</source>
        <translation>ضُبط DT على %1 s</translation>
    </message>
    <message>
        <source>Use implicit-euler</source>
        <translation>استخدم implicit-euler</translation>
    </message>
    <message>
        <source>Linearised backward Euler: stable at any DT (and damps more)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Keep DT</source>
        <translation>أبقِ DT</translation>
    </message>
    <message>
        <source>Run with this DT anyway (to watch the method fail, for example)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The 3D view needs OpenGL 3.3, which this display does not offer.
Plots, parameters and exports still work.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open scene</source>
        <translation>فتح مشهد</translation>
    </message>
    <message>
        <source>Could not open %1: %2</source>
        <translation>تعذر فتح %1: %2</translation>
    </message>
    <message>
        <source>Cannot build that body: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&amp;Language</source>
        <translation>ال&amp;لغة</translation>
    </message>
    <message>
        <source>System language</source>
        <translation>لغة النظام</translation>
    </message>
    <message>
        <source>Applies at the next start (now: %1)</source>
        <translation>يُطبَّق عند التشغيل التالي (الآن: %1)</translation>
    </message>
    <message>
        <source>The language changes when Elastic Lab starts again.</source>
        <translation>تتغير اللغة عند إعادة تشغيل Elastic Lab.</translation>
    </message>
    <message>
        <source>Language: %1 at the next start</source>
        <translation>اللغة: %1 عند التشغيل التالي</translation>
    </message>
    <message>
        <source>Language</source>
        <translation>اللغة</translation>
    </message>
    <message>
        <source>Class controls</source>
        <translation>أزرار الصف</translation>
    </message>
    <message>
        <source>Presentation mode: text %1x (Ctrl+= larger, Ctrl+- smaller, F5 off)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Normal text size</source>
        <translation>حجم النص العادي</translation>
    </message>
    <message>
        <source>Unsaved changes</source>
        <translation>تغييرات غير محفوظة</translation>
    </message>
    <message>
        <source>The parameters or the integrator of %1 have changed since it was saved.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save stores the changes and the current state in the file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> Press Run (Space).</source>
        <translation> اضغط تشغيل (مسافة).</translation>
    </message>
    <message>
        <source>&amp;Pause</source>
        <translation>إي&amp;قاف مؤقت</translation>
    </message>
    <message>
        <source>&amp;Run</source>
        <translation>&amp;تشغيل</translation>
    </message>
    <message>
        <source>&lt;b&gt;This body is likely unstable at the current DT.&lt;/b&gt; %1. The run is paused.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Use DT = %1 s</source>
        <translation>استخدم DT = %1 s</translation>
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
        <translation>(لا شيء)</translation>
    </message>
    <message>
        <source>&amp;Clear</source>
        <translation>م&amp;سح</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json);;All files (*)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1: not a regular file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1: no such file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not open %1: %2 bytes is too large for a scene file</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 is not a scene this program can open:
%2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1: the saved state at t = %2 s, paused. Press Run (Space).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Opened %1 (no saved state: starts at t = 0). Press Run (Space).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 no longer exists; it has been removed from the recent files.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Open recent</source>
        <translation>فُتح مؤخرًا</translation>
    </message>
    <message>
        <source>Save scene as</source>
        <translation>حفظ المشهد باسم</translation>
    </message>
    <message>
        <source>Elastic Lab scenes (*.json)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Could not save %1: no scene is running yet</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save scene</source>
        <translation>حفظ المشهد</translation>
    </message>
    <message>
        <source>Saved the first view (%1) at t = %2 s to %3; %4 not in the file.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the second view is</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the other views are</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Saved %1 at t = %2 s (%3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV, comma and decimal point (*.csv)</source>
        <translation>CSV، فاصلة ونقطة عشرية (*.csv)</translation>
    </message>
    <message>
        <source>CSV for spreadsheets, semicolon and decimal comma (*.csv)</source>
        <translation>CSV لجداول البيانات، فاصلة منقوطة وفاصلة عشرية (*.csv)</translation>
    </message>
    <message>
        <source>Excel workbook with charts (*.xlsx)</source>
        <translation>مصنف Excel مع رسوم بيانية (*.xlsx)</translation>
    </message>
    <message>
        <source>Export data</source>
        <translation>تصدير البيانات</translation>
    </message>
    <message>
        <source>Wrote %1 rows to %2</source>
        <translation>كُتب %1 صفًا إلى %2</translation>
    </message>
    <message>
        <source>Export plots</source>
        <translation>تصدير الرسوم</translation>
    </message>
    <message>
        <source>PNG image (*.png);;SVG drawing (*.svg);;PDF document (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>كُتب %1</translation>
    </message>
    <message>
        <source>Save viewport screenshot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>PNG image (*.png)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Save screenshot</source>
        <translation>حفظ اللقطة</translation>
    </message>
    <message>
        <source>Step &amp;back</source>
        <translation>خطوة لل&amp;خلف</translation>
    </message>
    <message>
        <source>Timeline s&amp;tart</source>
        <translation>&amp;بداية الخط الزمني</translation>
    </message>
    <message>
        <source>Timeline &amp;newest</source>
        <translation>الأ&amp;حدث</translation>
    </message>
    <message>
        <source>&amp;Clear abandoned future</source>
        <translation>مسح المستقبل ال&amp;متروك</translation>
    </message>
    <message>
        <source>Velocity vectors</source>
        <translation>متجهات السرعة</translation>
    </message>
    <message>
        <source>Ruler (drag to measure)</source>
        <translation>المسطرة (اسحب للقياس)</translation>
    </message>
    <message>
        <source>Lesson &amp;texts (Experiments)...</source>
        <translation>&amp;نصوص الدروس (التجارب)...</translation>
    </message>
    <message>
        <source>&amp;Lessons</source>
        <translation>ال&amp;دروس</translation>
    </message>
    <message>
        <source>%1: set up. Lessons &gt; Lesson texts says what to change and what to look at. Press Run (Space).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plotting the %1 against time (the Measured dock).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Particle %1</source>
        <translation>الجسيم %1</translation>
    </message>
    <message>
        <source>Plot its height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot its speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot the inner layer&apos;s centre height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot the outer layer&apos;s centre height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Body</source>
        <translation>الجسم</translation>
    </message>
    <message>
        <source>Plot the centre-of-mass height</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot the centre-of-mass speed</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Plot the layers&apos; separation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Several &amp;bodies</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1: several bodies. The Bodies dock shows momentum and min_gap; Parameters has a body selector. Press Run (Space).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Long-time energy</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Side by side</source>
        <translation type="unfinished">جنبًا إلى جنب</translation>
    </message>
</context>
<context>
    <name>elui::MeasurePlotDock</name>
    <message>
        <source>Measured</source>
        <translation>المقيس</translation>
    </message>
    <message>
        <source>Right-click a particle or the body in the view to plot it here.</source>
        <translation>انقر بالزر الأيمن على جسيم أو على الجسم في العرض لرسمه هنا.</translation>
    </message>
    <message>
        <source>Remove all</source>
        <translation>أزل الكل</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>length [m]</source>
        <translation>الطول [m]</translation>
    </message>
    <message>
        <source>speed [m/s]</source>
        <translation>السرعة [m/s]</translation>
    </message>
</context>
<context>
    <name>elui::Pacer</name>
    <message>
        <source>Real time</source>
        <translation>الزمن الحقيقي</translation>
    </message>
    <message>
        <source>1/4 speed</source>
        <translation>ربع السرعة</translation>
    </message>
    <message>
        <source>1/10 speed</source>
        <translation>عُشر السرعة</translation>
    </message>
    <message>
        <source>As fast as possible</source>
        <translation>بأسرع ما يمكن</translation>
    </message>
</context>
<context>
    <name>elui::ParameterDock</name>
    <message>
        <source>Parameters</source>
        <translation>المعاملات</translation>
    </message>
    <message>
        <source>Every parameter of the scene with its unit; a change applies at once</source>
        <translation>كل معاملات المشهد مع وحداتها؛ يُطبَّق التغيير فورًا</translation>
    </message>
    <message>
        <source>Reset all to the scene&apos;s defaults</source>
        <translation>الكل إلى القيم الافتراضية</translation>
    </message>
    <message>
        <source>Every parameter here (and DT) back to the scene&apos;s default; the body&apos;s shape stays (Scene dock).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The body whose parameters are shown and edited; world parameters (gravity, box, contact, dt) are every body&apos;s.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>body%1 (%2)</source>
        <translation>الجسم%1 (%2)</translation>
    </message>
    <message>
        <source>every body</source>
        <translation>كل الأجسام</translation>
    </message>
</context>
<context>
    <name>elui::ParameterForm</name>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;default: %3</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;&lt;br&gt;%2&lt;br&gt;الافتراضي: %3</translation>
    </message>
    <message>
        <source>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;allowed: %4&lt;br&gt;default: %5</source>
        <translation>&lt;b&gt;%1&lt;/b&gt;%2&lt;br&gt;%3&lt;br&gt;المسموح: %4&lt;br&gt;الافتراضي: %5</translation>
    </message>
    <message>
        <source>Set DT in the Run dock.</source>
        <translation>اضبط DT في لوحة التشغيل.</translation>
    </message>
    <message>
        <source>key: %1</source>
        <translation>المفتاح: %1</translation>
    </message>
    <message>
        <source>%1: &apos;%2&apos; is not a number; allowed %3</source>
        <translation>%1: &apos;%2&apos; ليس عددًا؛ المسموح %3</translation>
    </message>
    <message>
        <source>%1 = %2 is not allowed; allowed %3%4</source>
        <translation>%1 = %2 غير مسموح؛ المسموح %3%4</translation>
    </message>
    <message>
        <source>, whole numbers</source>
        <translation>، أعداد صحيحة</translation>
    </message>
    <message>
        <source>Back to the default: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Back to the default: %1 %2</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>%1 from %2 to %3 %4%5 (the field takes any value in %6)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>, logarithmic</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::PlotDock</name>
    <message>
        <source>Plots</source>
        <translation>الرسوم البيانية</translation>
    </message>
    <message>
        <source>Last 5 s</source>
        <translation>آخر 5 s</translation>
    </message>
    <message>
        <source>Last 10 s</source>
        <translation>آخر 10 s</translation>
    </message>
    <message>
        <source>Last 30 s</source>
        <translation>آخر 30 s</translation>
    </message>
    <message>
        <source>Full history</source>
        <translation>السجل الكامل</translation>
    </message>
    <message>
        <source>Autoscale</source>
        <translation>تحجيم تلقائي</translation>
    </message>
    <message>
        <source>Fit the axes to the data; off while you zoom (wheel) and pan (drag)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show per-step error band</source>
        <translation>إظهار نطاق الخطأ لكل خطوة</translation>
    </message>
    <message>
        <source>A band around volume, pressure and total energy: the integrator&apos;s local error estimate of each step carried to them (|O(y + e) - O(y)|): the error one step adds, not the error of the run so far, which can be far larger. rk45, CVODE and step doubling have an estimate; other methods show no band.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time window of the plots</source>
        <translation>النافذة الزمنية للرسوم</translation>
    </message>
    <message>
        <source>How much of the run the plots show: the last seconds, or all of it</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Show</source>
        <translation>إظهار</translation>
    </message>
    <message>
        <source>Energy drift per view</source>
        <translation>انجراف الطاقة لكل عرض</translation>
    </message>
    <message>
        <source>t [s]</source>
        <translation>t [s]</translation>
    </message>
    <message>
        <source>|drift| [J]</source>
        <translation>|الانجراف| [J]</translation>
    </message>
    <message>
        <source>✕ a view failed</source>
        <translation>✕ فشل أحد العروض</translation>
    </message>
    <message>
        <source>%1 against simulated time; the numbers are in the Run dock&apos;s readout and in File &gt; Export Data</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>total</source>
        <translation>الكلية</translation>
    </message>
    <message>
        <source> (abandoned)</source>
        <translation> (متروك)</translation>
    </message>
    <message>
        <source> error band</source>
        <translation> نطاق الخطأ</translation>
    </message>
    <message>
        <source>No band: this integrator gives no error estimate. Use rk45, CVODE, or tick &quot;Estimate error (step doubling)&quot; in the Run dock.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The band is there but thinner than a line: each step&apos;s error estimate is below half a pixel at this zoom (an adaptive method keeps it under its tolerance). Loosen rtol/atol in the Run dock, or use a fixed-step method at a larger DT with step doubling, to see it.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Band: the error each step adds (a per-step estimate), not the error of the run so far.</source>
        <translation type="unfinished"></translation>
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
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference curve (rk45)</source>
        <translation>منحنى مرجعي (rk45)</translation>
    </message>
    <message>
        <source>A converged solution (rk45 at tolerance 1e-10) from the run&apos;s start, computed beside the run on a thread of its own and drawn dashed: the distance between a curve and it is the error of the run so far (the global error), where the band is the error one step adds. It follows the run up to the first change of the physics (a parameter edit other than DT, or a drag).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reference (rk45, 1e-10)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference: computing from the run&apos;s start…</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>At t = %1 s the run&apos;s total energy is %2 J from the reference: the error of the run so far.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The band there, one step&apos;s error: ±%1 J.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The reference itself failed at t = %1 s (%2): the body fails at every step size.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The run was changed at t = %1 s (a parameter edit or a drag): the reference stops there.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The reference has reached t = %1 s (computing).</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::PvDock</name>
    <message>
        <source>P–V diagram</source>
        <translation>مخطط P–V</translation>
    </message>
    <message>
        <source>Whole curve (0.5 to 1.5 × rest volume)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Off: the axes fit the trail, to see it move. On: a wide stretch of the isotherm, to see where on it the layer sits.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inner layer</source>
        <translation>الطبقة الداخلية</translation>
    </message>
    <message>
        <source>outer layer</source>
        <translation>الطبقة الخارجية</translation>
    </message>
    <message>
        <source>Pressure against volume, %1</source>
        <translation>الضغط مقابل الحجم، %1</translation>
    </message>
    <message>
        <source>The trail of the layer&apos;s gas in the P-V plane and its isotherm</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>P–V, %1</source>
        <translation>P–V، %1</translation>
    </message>
    <message>
        <source>trail</source>
        <translation>الأثر</translation>
    </message>
    <message>
        <source>now</source>
        <translation>الآن</translation>
    </message>
    <message>
        <source>area V [m²]</source>
        <translation>المساحة V [m²]</translation>
    </message>
    <message>
        <source>volume V [m³]</source>
        <translation>الحجم V [m³]</translation>
    </message>
    <message>
        <source>pressure P [N/m]</source>
        <translation>الضغط P [N/m]</translation>
    </message>
    <message>
        <source>pressure P [Pa]</source>
        <translation>الضغط P [Pa]</translation>
    </message>
    <message>
        <source>%1 has no gas: no P–V diagram.</source>
        <translation>%1 لا غاز فيه: لا مخطط P–V.</translation>
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
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Values of the scene&apos;s resolution, separated by spaces; the finest is the reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>automatic</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fixed step DT [s] for every level; it must divide 0.01 s and be stable at the finest level. Empty: a quarter of the smaller of the scene&apos;s DT and the finest level&apos;s stable step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Levels</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Levels (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>run time [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max relative volume error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max centre-of-mass error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose exactly one integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT must be a number in seconds, or empty for the automatic step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Levels are whole numbers separated by spaces, got &apos;%1&apos;</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>level (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>particles</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>springs</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>h [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>steps</source>
        <translation>الخطوات</translation>
    </message>
    <message>
        <source>volume error</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>centre-of-mass error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mesh (%1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>step (%1=%2, coarser DT)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Failed: %1</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time error of that step (measured at %1=%2): volume %3, centre of mass %4 m. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spatial order (%1): %2. </source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Spatial order (%1): not resolved. </source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::RunDock</name>
    <message>
        <source>Run</source>
        <translation>التشغيل</translation>
    </message>
    <message>
        <source>side by side (see each view)</source>
        <translation>جنبًا إلى جنب (انظر كل عرض)</translation>
    </message>
    <message>
        <source>Integrator</source>
        <translation>المكامل</translation>
    </message>
    <message>
        <source>The method that advances the body in time; each one&apos;s order and idea are in its item&apos;s tooltip and in Help</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>rk45, cvode-bdf and cvode-adams choose their steps so that each step&apos;s error estimate stays below atol + rtol |y| (as elastic-lab-cli --atol, --rtol). rtol in (0, 1], atol in [0, 1] (m and m/s). Smaller: smaller steps, more force evaluations, a thinner error band.</source>
        <translation type="unfinished"></translation>
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
        <translation>التسامح</translation>
    </message>
    <message>
        <source>How fast simulated time runs against the wall clock</source>
        <translation>مدى سرعة الزمن المحاكى مقارنة بالساعة</translation>
    </message>
    <message>
        <source>Speed</source>
        <translation>السرعة</translation>
    </message>
    <message>
        <source>Run or pause the simulation (Space)</source>
        <translation>شغّل المحاكاة أو أوقفها مؤقتًا (مسافة)</translation>
    </message>
    <message>
        <source>Step</source>
        <translation>خطوة</translation>
    </message>
    <message>
        <source>One step DT forward (S)</source>
        <translation>خطوة DT واحدة للأمام (S)</translation>
    </message>
    <message>
        <source>Reset</source>
        <translation>إعادة الضبط</translation>
    </message>
    <message>
        <source>Back to the start state with the same parameters (Ctrl+R)</source>
        <translation>العودة إلى حالة البداية بالمعاملات نفسها (Ctrl+R)</translation>
    </message>
    <message>
        <source>Estimate error (step doubling)</source>
        <translation>تقدير الخطأ (مضاعفة الخطوة)</translation>
    </message>
    <message>
        <source>Fixed-step integrators: estimate the local error by taking each step also as two half steps. Costs about twice the work. rk45 always reports its own estimate.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Readout</source>
        <translation>القراءات</translation>
    </message>
    <message>
        <source>Time, steps, energies and the energy balance of the run</source>
        <translation>الزمن والخطوات والطاقات وميزان الطاقة للتشغيل</translation>
    </message>
    <message>
        <source>rtol: &apos;%1&apos; is not a number in (0, 1]</source>
        <translation>rtol: ‏&apos;%1&apos; ليس عددًا في (0, 1]</translation>
    </message>
    <message>
        <source>atol: &apos;%1&apos; is not a number in [0, 1]</source>
        <translation>atol: ‏&apos;%1&apos; ليس عددًا في [0, 1]</translation>
    </message>
    <message>
        <source>Each view</source>
        <translation>كل عرض</translation>
    </message>
    <message>
        <source>view</source>
        <translation>العرض</translation>
    </message>
    <message>
        <source>time</source>
        <translation>الزمن</translation>
    </message>
    <message>
        <source>steps</source>
        <translation>الخطوات</translation>
    </message>
    <message>
        <source>energy drift</source>
        <translation>انجراف الطاقة</translation>
    </message>
    <message>
        <source>failed</source>
        <translation>فشل</translation>
    </message>
    <message>
        <source>Pause</source>
        <translation>إيقاف مؤقت</translation>
    </message>
    <message>
        <source>simulated time</source>
        <translation>الزمن المحاكى</translation>
    </message>
    <message>
        <source>wall time</source>
        <translation>زمن الساعة</translation>
    </message>
    <message>
        <source>steps/s</source>
        <translation>خطوة/s</translation>
    </message>
    <message>
        <source>paused</source>
        <translation>متوقف مؤقتًا</translation>
    </message>
    <message>
        <source>step taken</source>
        <translation>الخطوة المتخذة</translation>
    </message>
    <message>
        <source>error estimate</source>
        <translation>تقدير الخطأ</translation>
    </message>
    <message>
        <source>off</source>
        <translation>معطل</translation>
    </message>
    <message>
        <source>contact energy</source>
        <translation>طاقة التلامس</translation>
    </message>
    <message>
        <source>removed by contact</source>
        <translation>أزالها التلامس</translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>حسابات القوة</translation>
    </message>
    <message>
        <source>CVODE steps / RHS</source>
        <translation>خطوات CVODE / RHS</translation>
    </message>
    <message>
        <source>Jv products / linear it.</source>
        <translation>جداءات Jv / تكرارات خطية</translation>
    </message>
    <message>
        <source>error-test / conv. failures</source>
        <translation>إخفاقات اختبار الخطأ / التقارب</translation>
    </message>
    <message>
        <source>order, re-initialisations</source>
        <translation>الرتبة، إعادات التهيئة</translation>
    </message>
    <message>
        <source>&lt;p style=&apos;color:#b35900&apos;&gt;Cannot keep up with real time: showing as fast as it runs.&lt;/p&gt;</source>
        <translation>&lt;p style=&apos;color:#b35900&apos;&gt;لا يمكن مجاراة الزمن الحقيقي: يُعرض بأسرع ما يحسب.&lt;/p&gt;</translation>
    </message>
    <message>
        <source>order %1: %2</source>
        <translation>الرتبة %1: %2</translation>
    </message>
    <message>
        <source>%1; allowed %2 s</source>
        <translation>%1؛ المسموح %2 s</translation>
    </message>
    <message>
        <source>Relative tolerance rtol</source>
        <translation>التسامح النسبي rtol</translation>
    </message>
    <message>
        <source>Absolute tolerance atol</source>
        <translation>التسامح المطلق atol</translation>
    </message>
    <message>
        <source>Run</source>
        <comment>button: start the simulation</comment>
        <translation>تشغيل</translation>
    </message>
    <message>
        <source>distance&lt;br&gt;to view %1</source>
        <translation>المسافة&lt;br&gt;إلى العرض %1</translation>
    </message>
    <message>
        <source>double</source>
        <translation>مزدوجة (64 بت)</translation>
    </message>
    <message>
        <source>float</source>
        <translation>مفردة (32 بت)</translation>
    </message>
    <message>
        <source>double: state and forces in 64-bit numbers. float: in 32-bit numbers, as fast engines and games compute (euler, midpoint, rk4, symplectic-euler, verlet; one view; no walls or mouse: the run stops at a wall, a held particle steps in double). The readout shows how far the float run is from double.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Precision</source>
        <translation>الدقة</translation>
    </message>
    <message>
        <source>precision</source>
        <translation>الدقة</translation>
    </message>
    <message>
        <source>double while held</source>
        <translation>مزدوجة أثناء السحب</translation>
    </message>
    <message>
        <source>float − double</source>
        <translation>مفردة − مزدوجة</translation>
    </message>
    <message>
        <source>round-off (est.)</source>
        <translation>خطأ التقريب (تقدير)</translation>
    </message>
</context>
<context>
    <name>elui::SceneDock</name>
    <message>
        <source>Scene</source>
        <translation>المشهد</translation>
    </message>
    <message>
        <source>The body to build: a spring, a two-layer ring or a two-layer sphere</source>
        <translation>الجسم المراد بناؤه: نابض أو حلقة بطبقتين أو كرة بطبقتين</translation>
    </message>
    <message>
        <source>Rebuild body</source>
        <translation>أعد بناء الجسم</translation>
    </message>
    <message>
        <source>Build the chosen scene with this shape and start again from rest</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Body values</source>
        <translation>قيم الجسم</translation>
    </message>
    <message>
        <source>What the parameters mean for the body that runs: under scaling=physical the values hold at the scene&apos;s default resolution and a finer mesh keeps the body&apos;s totals; under scaling=thesis they are per particle and per spring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>This body uses: %1</source>
        <translation>يستخدم هذا الجسم: %1</translation>
    </message>
    <message>
        <source>The body to build, its shape and what its parameters mean</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::StabilityDialog</name>
    <message>
        <source>Stability scan</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each trial runs this long; a run that does not blow up and whose energy stays bounded is stable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>largest stable DT [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linearising</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>stable DT [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>unstable DT [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>predicted DT [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>h·ω at stable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>why it failed above</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>measured</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linearised prediction</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Highest mode of the linearised body: ω = %1 rad/s (damping %2 1/s), %3 free coordinates. A method is stable at DT when no mode grows; measured by bisection over %4 s runs.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration must be a positive number of seconds</source>
        <translation>يجب أن تكون المدة عددًا موجبًا من الثواني</translation>
    </message>
</context>
<context>
    <name>elui::StabilityMapDock</name>
    <message>
        <source>Stability map</source>
        <translation>خريطة الاستقرار</translation>
    </message>
    <message>
        <source>The integrator&apos;s stability region and the body&apos;s eigenvalues times DT; the margin is written below the map</source>
        <translation>منطقة استقرار المكامل والقيم الذاتية للجسم مضروبة في DT؛ الهامش مكتوب تحت الخريطة</translation>
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
        <translation>منطقة الاستقرار</translation>
    </message>
    <message>
        <source>DT·λ, every mode</source>
        <translation>DT·λ، كل الأنماط</translation>
    </message>
    <message>
        <source>leaves first</source>
        <translation>يخرج أولًا</translation>
    </message>
    <message>
        <source>measured limit</source>
        <translation>الحدّ المقيس</translation>
    </message>
    <message>
        <source>Try it</source>
        <translation>جرّبه</translation>
    </message>
    <message>
        <source>Waiting for a body…</source>
        <translation>بانتظار جسم…</translation>
    </message>
    <message>
        <source>Linearising the body…</source>
        <translation>جارٍ حساب النموذج الخطي للجسم…</translation>
    </message>
    <message>
        <source>edge (radius 1)</source>
        <translation>الحافة (نصف القطر 1)</translation>
    </message>
    <message>
        <source>edge |R| = 1</source>
        <translation>الحافة |R| = 1</translation>
    </message>
    <message>
        <source>edge of view %1 (%2)</source>
        <translation>حافة العرض %1 (%2)</translation>
    </message>
    <message>
        <source>Re(hλ), h = DT = %1 s</source>
        <translation>Re(hλ)، h = DT = %1 s</translation>
    </message>
    <message>
        <source>View %1, %2 (filled): %3</source>
        <translation>العرض %1، %2 (مملوء): %3</translation>
    </message>
    <message>
        <source>View %1, %2 (dashed): %3</source>
        <translation>العرض %1، %2 (متقطّع): %3</translation>
    </message>
    <message>
        <source>Eigenvalues: %1.
%2</source>
        <translation>القيم الذاتية: %1.
%2</translation>
    </message>
    <message>
        <source>%1 has no fixed stability limit to measure</source>
        <translation>ليس لـ %1 حدّ استقرار ثابت يُقاس</translation>
    </message>
    <message>
        <source>Measured: no stable DT down to 1e-5 s.</source>
        <translation>المقيس: لا DT مستقرًا حتى 1e-5 s.</translation>
    </message>
    <message>
        <source>Measured: stable up to the largest DT scanned, %1 s</source>
        <translation>المقيس: مستقر حتى أكبر DT جرى مسحه، %1 s</translation>
    </message>
    <message>
        <source>Measured: stable at DT = %1 s, blows up at %2 s</source>
        <translation>المقيس: مستقر عند DT = %1 s، وينفجر عند %2 s</translation>
    </message>
    <message>
        <source> (%1 runs of %2 s; predicted %3 s).</source>
        <translation> (%1 تشغيلًا مدة كل منها %2 s؛ المتوقَّع %3 s).</translation>
    </message>
    <message>
        <source>unlimited</source>
        <translation>غير محدود</translation>
    </message>
    <message>
        <source> ✕ = the ringed mode at the measured DT.</source>
        <translation> ✕ = النمط المطوَّق عند DT المقيس.</translation>
    </message>
    <message>
        <source> ✕ = the fastest mode at the measured DT.</source>
        <translation> ✕ = النمط الأسرع عند DT المقيس.</translation>
    </message>
    <message>
        <source>Measuring the largest stable DT of %1…</source>
        <translation>جارٍ قياس أكبر DT مستقر لـ %1…</translation>
    </message>
    <message>
        <source>Cancelling…</source>
        <translation>جارٍ الإلغاء…</translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>إلغاء</translation>
    </message>
    <message>
        <source>Measurement cancelled.</source>
        <translation>أُلغي القياس.</translation>
    </message>
    <message>
        <source>The body or the integrator changed during the measurement: press Try it again.</source>
        <translation>تغيّر الجسم أو المكامل أثناء القياس: اضغط «جرّبه» مرة أخرى.</translation>
    </message>
    <message>
        <source>Measure this integrator&apos;s largest stable DT on this body or world: the stability scan&apos;s bisection (%1 s runs; Studies → Stability scan does all integrators), marked on the picture</source>
        <translation>قِس أكبر DT مستقر لهذا المكامل على هذا الجسم أو العالم: تنصيف مسح الاستقرار (تشغيلات مدة كل منها %1 s؛ دراسات ← مسح الاستقرار يفعل ذلك لكل المكاملات)، ويُعلَّم على الصورة</translation>
    </message>
    <message>
        <source>Linearising the world (%1 bodies)…</source>
        <translation>جارٍ حساب النموذج الخطي للعالم (%1 أجسام)…</translation>
    </message>
    <message>
        <source>The whole world (%1 bodies) linearised as one system: every body&apos;s modes, and the contact between bodies where two are within the contact skin. </source>
        <translation>العالم كله (%1 أجسام) في نموذج خطي واحد: أنماط كل جسم، والتلامس بين الأجسام حيث يقع جسمان ضمن قشرة التلامس. </translation>
    </message>
    <message>
        <source>the fastest mode</source>
        <translation>النمط الأسرع</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1, a pure decay)</source>
        <translation>النمط الأسرع (hλ = %1، اضمحلال بحت)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1, a pure decay)</source>
        <translation>النمط (hλ = %1، اضمحلال بحت)</translation>
    </message>
    <message>
        <source>the fastest mode (hλ = %1 ± %2i)</source>
        <translation>النمط الأسرع (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>the mode (hλ = %1 ± %2i)</source>
        <translation>النمط (hλ = %1 ± %2i)</translation>
    </message>
    <message>
        <source>per mode, modal damping</source>
        <translation>نمطًا نمطًا، بتخميد نمطي</translation>
    </message>
    <message>
        <source>xpbd is stable at every DT: no margin to give.</source>
        <translation>xpbd مستقر عند كل DT: لا هامش يُذكر.</translation>
    </message>
    <message>
        <source>%1 chooses its own internal steps: no DT limit from stability.</source>
        <translation>%1 يختار خطواته الداخلية بنفسه: لا حدّ على DT من الاستقرار.</translation>
    </message>
    <message>
        <source>No DT limit: every mode of this body stays in the region for any DT.</source>
        <translation>لا حدّ على DT: يبقى كل نمط من أنماط هذا الجسم داخل المنطقة عند أي DT.</translation>
    </message>
    <message>
        <source>No DT is stable: a mode pair grows for every DT (%1).</source>
        <translation>لا DT مستقرًا: زوج من الأنماط ينمو عند كل DT (%1).</translation>
    </message>
    <message>
        <source>No DT is stable: %1 sits where the region only touches the imaginary axis at 0; it grows for every DT (slowly when DT is small).</source>
        <translation>لا DT مستقرًا: يقع %1 حيث لا تمسّ المنطقة المحور التخيلي إلا عند 0؛ فهو ينمو عند كل DT (ببطء حين يكون DT صغيرًا).</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before a mode pair goes unstable (%3); the picture is exact for underdamped modes only.</source>
        <translation>يمكن أن يكبر DT بمعامل %1 (حتى %2 s) قبل أن يصير زوج من الأنماط غير مستقر (%3)؛ الصورة دقيقة للأنماط ناقصة التخميد فقط.</translation>
    </message>
    <message>
        <source>DT can grow %1× (to %2 s) before %3 leaves the region.</source>
        <translation>يمكن أن يكبر DT بمعامل %1 (حتى %2 s) قبل أن يخرج %3 من المنطقة.</translation>
    </message>
    <message>
        <source>DT is already outside the stable range (%1): shrink DT by %2× (to %3 s).</source>
        <translation>DT خارج المجال المستقر أصلًا (%1): صغّر DT بمعامل %2 (إلى %3 s).</translation>
    </message>
    <message>
        <source>DT is already outside: %1 is out of the region; shrink DT by %2× (to %3 s) to bring it back.</source>
        <translation>DT كبير أصلًا: %1 خارج المنطقة؛ صغّر DT بمعامل %2 (إلى %3 s) لإعادته إليها.</translation>
    </message>
    <message>
        <source>exact spectrum: all %1 eigenvalues of the linearised first-order system (dense eigen-solve)</source>
        <translation>الطيف الدقيق: كل القيم الذاتية الـ %1 للنظام الخطي من الرتبة الأولى (حلّ كثيف للقيم الذاتية)</translation>
    </message>
    <message>
        <source>modal: all %1 modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; λ = −c/2 ± i√(ω² − c²/4)</source>
        <translation>نمطي: كل الأنماط الـ %1 لـ M⁻¹K (مسألة قيم ذاتية متماثلة)، والتخميد c = φᵀ(M⁻¹D)φ لكل نمط؛ λ = −c/2 ± i√(ω² − c²/4)</translation>
    </message>
    <message>
        <source>iterative: %1 Ritz values of the first-order system, Arnoldi (%2 steps) on the Jacobian products, %3 free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner ones are not</source>
        <translation>تكراري: %1 قيمة ريتز للنظام من الرتبة الأولى، أرنولدي (%2 خطوة) على جداءات المصفوفة اليعقوبية، %3 إحداثيًا حرًّا: القيم الذاتية القصوى (أكبر |λ|) دقيقة، والداخلية ليست كذلك</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis up to ±%1i: undamped modes are stable up to hω = 2√2.</source>
        <translation>المنطقة: |R(hλ)| ≤ 1 لكثيرة حدود الاستقرار R (كثيرة حدود تايلور لـ e^z)؛ تمسّ المحور التخيلي حتى ±%1i: الأنماط غير المخمَّدة مستقرة حتى hω = 2√2.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it touches the imaginary axis only at 0: an undamped mode grows for every DT.</source>
        <translation>المنطقة: |R(hλ)| ≤ 1 لكثيرة حدود الاستقرار R (كثيرة حدود تايلور لـ e^z)؛ لا تمسّ المحور التخيلي إلا عند 0: النمط غير المخمَّد ينمو عند كل DT.</translation>
    </message>
    <message>
        <source>Region: |R(hλ)| ≤ 1 for Dormand–Prince&apos;s 5th-order solution, R = Taylor to z⁵ + z⁶/600, taken at a fixed step. The adaptive run picks its own step from the error tolerance: it does not blow up, it takes smaller steps.</source>
        <translation>المنطقة: |R(hλ)| ≤ 1 لحلّ دورماند–برنس من الرتبة الخامسة، R = تايلور حتى z⁵ + z⁶/600، مأخوذة بخطوة ثابتة. التشغيل المتكيّف يختار خطوته بنفسه من تسامح الخطأ: لا ينفجر، بل يأخذ خطوات أصغر.</translation>
    </message>
    <message>
        <source>Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| &lt; 1, the whole left half-plane (A-stable): no DT limit from stability.</source>
        <translation>المنطقة: |1/(1 − hλ)| ≤ 1، أي كل ما هو خارج القرص |1 − hλ| &lt; 1، وهو نصف المستوى الأيسر كله (مستقرة من النوع A): لا حدّ على DT من الاستقرار.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>المنطقة: لا R عددية؛ مرسومة لنمط مهتزّ زوج قيمه الذاتية hλ، hλ̄ (دقيقة حين تنفصل الأنماط؛ المحور الحقيقي يُظهر النمط ذا التخميد الحرج). الأنماط غير المخمَّدة: hω ≤ 2. الهامش من مصفوفة الخطوة، لا من الصورة.</translation>
    </message>
    <message>
        <source>Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, damping at the half-step velocity (exact when the modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.</source>
        <translation>المنطقة: لا R عددية؛ مرسومة لنمط مهتزّ زوج قيمه الذاتية hλ، hλ̄، والتخميد عند سرعة نصف الخطوة (دقيقة حين تنفصل الأنماط؛ المحور الحقيقي يُظهر النمط ذا التخميد الحرج). الأنماط غير المخمَّدة: hω ≤ 2. الهامش من مصفوفة الخطوة، لا من الصورة.</translation>
    </message>
    <message>
        <source>Region: no scalar R; the step is a product of %1 Verlet substeps (some backwards), drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the half-kick velocity, as the integrator does), traced ray by ray from 0. Undamped modes: hω ≤ %2 (a step costs %3 force evaluations). The margin uses the step matrix, not the picture.</source>
        <translation>المنطقة: لا R عددية؛ الخطوة جداء %1 خطوة فرعية من خطوات فيرليه (بعضها إلى الوراء)، مرسومة لنمط مهتزّ زوج قيمه الذاتية hλ، hλ̄ (التخميد عند سرعة نصف الدفعة، كما يفعل المكامل)، متتبَّعة شعاعًا شعاعًا من 0. الأنماط غير المخمَّدة: hω ≤ %2 (تكلّف الخطوة %3 حسابات للقوة). الهامش من مصفوفة الخطوة، لا من الصورة.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed region. BDF1–2 are A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the step or the order when a mode threatens: no DT limit, DT is only the output interval.</source>
        <translation>لا منطقة: BDF متكيّف متغيّر الرتبة (الرتب 1–5)، يضبط الخطأ، بلا منطقة ثابتة. BDF1–2 مستقرة من النوع A، وBDF3–5 مستقرة من النوع A(α) حتى α ≈ 51°؛ يصغّر CVODE الخطوة أو الرتبة حين يهدّد نمطٌ بالنمو: لا حدّ على DT، وDT هو فترة الإخراج فقط.</translation>
    </message>
    <message>
        <source>No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed region. Its regions are small (explicit-like); CVODE keeps the internal step inside them by its error test: no DT limit, stiff bodies only cost steps.</source>
        <translation>لا منطقة: طريقة آدمز متكيّفة متغيّرة الرتبة (الرتب 1–12)، تضبط الخطأ، بلا منطقة ثابتة. مناطقها صغيرة (كمناطق الطرق الصريحة)؛ يُبقي CVODE الخطوة الداخلية داخلها باختبار الخطأ: لا حدّ على DT، والأجسام الصلبة لا تكلّف إلا خطوات أكثر.</translation>
    </message>
    <message>
        <source>No region: XPBD projects the springs as compliant constraints (compliance 1/ks): unconditionally stable, no region in the hλ plane; large DT costs accuracy (the body turns soft), not stability.</source>
        <translation>لا منطقة: يُسقط XPBD النوابض قيودًا مرنة (مطاوعة 1/ks): مستقر دون شرط، لا منطقة في المستوى hλ؛ الـ DT الكبير يكلّف الدقة (يصير الجسم ليّنًا)، لا الاستقرار.</translation>
    </message>
    <message>
        <source>No stability region for %1.</source>
        <translation>لا منطقة استقرار لـ %1.</translation>
    </message>
</context>
<context>
    <name>elui::StrainLegend</name>
    <message>
        <source>spring strain</source>
        <translation>انفعال النابض</translation>
    </message>
</context>
<context>
    <name>elui::StudyDialogBase</name>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt; with the current parameters</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Include %1 (order %2) in the study: %3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Run</source>
        <translation>التشغيل</translation>
    </message>
    <message>
        <source>Run the study on a worker thread; the window stays usable</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancel</source>
        <translation>إلغاء</translation>
    </message>
    <message>
        <source>Stop the study; the rows finished so far stay</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Write the table as CSV, or the plot as SVG, PNG or PDF</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Study plot</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The study&apos;s results drawn; the same numbers are in the table</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>One row per run of the study; the arrow keys move between the cells</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelled: partial results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Done</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Choose at least one integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cancelling...</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV table (*.csv);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>CSV table (*.csv);;SVG plot (*.svg);;PNG plot (*.png);;PDF plot (*.pdf)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export results</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Export</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Wrote %1</source>
        <translation>كُتب %1</translation>
    </message>
    <message>
        <source>Scene: &lt;b&gt;%1&lt;/b&gt;, %2 bodies, with the current parameters (the whole world: every run moves every body)</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>elui::TimelineDock</name>
    <message>
        <source>Timeline</source>
        <translation>الخط الزمني</translation>
    </message>
    <message>
        <source>|◀ Start</source>
        <translation>|◀ البداية</translation>
    </message>
    <message>
        <source>The start of the recorded run (Home)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>◀ Step back</source>
        <translation>◀ خطوة للخلف</translation>
    </message>
    <message>
        <source>One step back (Shift+S); S steps forward</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Newest ▶|</source>
        <translation>الأحدث ▶|</translation>
    </message>
    <message>
        <source>The newest recorded moment (End)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Clear abandoned</source>
        <translation>امسح المتروك</translation>
    </message>
    <message>
        <source>Remove the faint lines of the abandoned future from the plots</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>&lt;b&gt;Back in time&lt;/b&gt;: t = %1 s, step %2 of %3 · a change, Run or Step branches here</source>
        <translation>&lt;b&gt;عودة في الزمن&lt;/b&gt;: t = %1 s، الخطوة %2 من %3 · أي تغيير أو تشغيل أو خطوة يتفرع من هنا</translation>
    </message>
    <message>
        <source>t = %1 s, step %2 (newest) · recorded from t = %3 s</source>
        <translation>t = %1 s، الخطوة %2 (الأحدث) · مسجل منذ t = %3 s</translation>
    </message>
    <message>
        <source>%1 checkpoints / %2 steps · %3 of %4</source>
        <translation>%1 نقاط حفظ / %2 خطوات · %3 من %4</translation>
    </message>
    <message>
        <source>Every moment of the run: drag, or Tab to it and press the arrow keys (Page Up and Page Down: a twentieth of the run), to travel back in time (the run pauses)</source>
        <translation>كل لحظة من التشغيل: اسحب، أو انتقل إليه بالمفتاح Tab واضغط مفاتيح الأسهم (Page Up وPage Down: جزء من عشرين من التشغيل)، للعودة في الزمن (يتوقف التشغيل مؤقتًا)</translation>
    </message>
</context>
<context>
    <name>elui::Viewport</name>
    <message>
        <source>Simulation view</source>
        <translation>عرض المحاكاة</translation>
    </message>
    <message>
        <source>The body. Keyboard: arrow keys or Page Up and Page Down choose a particle and show the forces on it; Enter grabs it with the mouse spring, then the arrow keys drag it (Shift: ten times farther) and Enter or Escape lets go; Escape clears the choice.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Forces on particle %1</source>
        <translation>القوى على الجسيم %1</translation>
    </message>
    <message>
        <source>total (sum)</source>
        <translation>الكلية (المجموع)</translation>
    </message>
    <message>
        <source>arrows: 1 m = %1 N</source>
        <translation>الأسهم: 1 m = %1 N</translation>
    </message>
    <message>
        <source>click elsewhere to clear</source>
        <translation>انقر في مكان آخر للمسح</translation>
    </message>
    <message>
        <source>distance from %1: %2 m (RMS)</source>
        <translation>المسافة عن %1: %2 m (RMS)</translation>
    </message>
    <message>
        <source>Blew up at t = %1 s: %2</source>
        <translation>انفجرت عند t = %1 s: %2</translation>
    </message>
    <message>
        <source>%1 m</source>
        <translation>%1 m</translation>
    </message>
    <message>
        <source> (Δx %1, Δy %2)</source>
        <translation> (Δx %1، Δy %2)</translation>
    </message>
    <message>
        <source>Forces on particle %1 of body %2</source>
        <translation>القوى على الجسيم %1 من الجسم %2</translation>
    </message>
    <message>
        <source>momentum %1 kg m/s</source>
        <translation>كمية الحركة %1 kg m/s</translation>
    </message>
    <message>
        <source>min_gap %1 m</source>
        <translation>min_gap %1 m</translation>
    </message>
    <message>
        <source>min_gap beyond %1 m</source>
        <translation>min_gap أبعد من %1 m</translation>
    </message>
</context>
<context>
    <name>elui::WorkPrecisionDialog</name>
    <message>
        <source>Work-precision study</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Fixed steps DT [s], separated by spaces; T must be a multiple of each</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Simulated time of every run [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>What the errors are measured against: the closed form where there is one (exact), or a run of rk4 or rk45 with a much smaller step; auto chooses</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Each point is timed this many times; the plot shows the median run time with a band from the first to the third quartile (the same binary runs at two speeds on a shared machine)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>none</source>
        <translation>لا شيء</translation>
    </message>
    <message>
        <source>A run that takes longer [s] is recorded as not reached (no error), and so is every costlier point of its integrator: the curve stops there</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT values [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Duration T [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Timed runs per point</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Time budget per run [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>force evaluations</source>
        <translation>حسابات القوة</translation>
    </message>
    <message>
        <source>run time (median, band q1–q3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>The cost of a run on the left panel: the force evaluations it took (a count: the same on every machine and every run), or its run time, the median over the timed runs with a band from q1 to q3 (on a busy machine a curve can zigzag backwards)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Cost axis</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max position error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>DT [s]</source>
        <translation>DT [s]</translation>
    </message>
    <message>
        <source>run time [s] (median, band q1–q3)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>integrator</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>family</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>steps</source>
        <translation>الخطوات</translation>
    </message>
    <message>
        <source>force evals</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>run time q1 [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>median [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>q3 [s]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>error at T [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>max error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>RMS error [m]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>energy error [J]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>status</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Reference: %1 (its own error about %2 m). Run time: median of %3 timed runs per point, band q1–q3.</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> %1: order %2 (RMS %3).</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source> q1–q3</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>fastest of its family</source>
        <translation type="unfinished"></translation>
    </message>
</context>
<context>
    <name>simcore</name>
    <message>
        <source>structural spring stiffness KS, per spring (scaling=physical: at the reference resolution; a 2D chain keeps k L0, a 3D membrane keeps k)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>structural spring damping KD, per spring; scales like KS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radius and shear spring stiffness RKS, per spring (scaling=physical: at the reference resolution; in parallel, k times count stays fixed)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>radius and shear spring damping RKD, per spring; scales like RKS</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gas constant nRT of each closed layer (PRESSURE): P = nRT / V</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the inner layer (defaults to pressure)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>nRT of the gas enclosed by the outer layer (defaults to pressure)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>particle mass MASS (scaling=physical: at the reference resolution; each layer keeps its total)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>inner-layer particle mass (defaults to mass; scaled like mass): real inertia, not scaled gravity</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>outer-layer particle mass (defaults to mass; scaled like mass)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>gravitational acceleration, pointing along -y</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>half-size of the collision box (floor, ceiling, walls), centred on the body&apos;s start</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>contact model: 0 = force (smooth penalty force inside the ODE, in the energy ledger), 1 = projection (the thesis program: put back and reflect after the step)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>coefficient of restitution e at the box walls: a particle hitting at contact_speed rebounds at e times its speed (projection: v_n becomes -e*v_n)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>k of the contact potential U = k d^4/4 per particle at a wall (d: penetration) and of the layer barrier (scaling=physical: at the reference resolution, scaled like mass)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>impact speed at which the contact damping gives exactly the restitution e</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>wall friction: Coulomb coefficient mu (force); tangential velocity fraction removed (projection)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>slip speed below which Coulomb friction is smoothed (regularised) [force contact]</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mouse spring stiffness (MKS)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>mouse spring damping (MKD)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rest length of the mouse spring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>time step DT of fixed-step integrators (initial step of adaptive ones)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>xpbd: substeps per step DT, one constraint iteration each (Macklin et al. 2019, small steps)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>what mass, ks, kd, rks, rkd and contact_stiffness mean when the mesh is refined: 0 = physical (the values hold at the scene&apos;s default resolution and the body keeps its totals and material constants), 1 = thesis (per particle and per spring at every resolution)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>particles per layer of the 2D ring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>subdivision level L of the octahedron sphere: 4*4^L+2 particles per layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>meridians of the lat/long sphere</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>latitude bands of the lat/long sphere (pole to pole)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rest radius of the inner layer (must be below radius_outer)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rest radius of the outer layer</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>rest length of the 1D spring</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>distance between the two particles at the start (the spring hangs along -y)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1: the top particle is fixed in space (thesis fig. 7); 0: both particles move</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>amplitude of a seeded random displacement of the start positions (breaks symmetry)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>seed of the start perturbation</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>1D: two masses on one spring hanging along -y, the top one fixed (thesis fig. 7)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>2D: two concentric gas-filled rings joined by radius and shear springs (thesis 3.4)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled spheres, subdivided octahedron (thesis 3.5.2)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>3D: two concentric gas-filled lat/long spheres, the non-uniform sphere (thesis 3.5.1)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>explicit Euler: x and v both from the old state (thesis eq. 22)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>the thesis&apos;s midpoint (eq. 31-33), i.e. Heun&apos;s RK2: two force evaluations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>classical Runge-Kutta 4 (eq. 35-40): four force evaluations</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>semi-implicit Euler: v from the old forces, then x from the new v</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>velocity Verlet (order 1 when damping is on: damping is taken at the half-step velocity)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yoshida&apos;s 4th-order composition of velocity Verlet: 3 substeps (one backwards), 4 force evaluations (order 1 with damping)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Yoshida&apos;s 8th-order composition of velocity Verlet (solution D): 15 substeps, 16 force evaluations (order 1 with damping)</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>Dormand-Prince 5(4): adaptive step from atol/rtol, embedded error estimate every step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>linearised backward Euler (Baraff-Witkin 1998): spring and gas Jacobians, matrix-free CG</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order BDF 1-5: Newton, matrix-free GMRES on the analytic Jacobian, implicit-euler&apos;s solve as preconditioner; adaptive from atol/rtol</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>extended position-based dynamics (Macklin et al. 2016, small steps 2019): springs as compliant distance constraints, `substeps` substeps of one iteration per step</source>
        <translation type="unfinished"></translation>
    </message>
    <message>
        <source>SUNDIALS CVODE, variable-order Adams-Moulton 1-12 with fixed-point iteration (non-stiff); adaptive from atol/rtol</source>
        <translation type="unfinished"></translation>
    </message>
</context>
</TS>
