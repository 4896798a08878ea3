#include "ui/help_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QTextBrowser>
#include <QUrl>
#include <QVBoxLayout>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "ui/parameter_dock.h"
#include "ui/presets.h"
#include "ui/lessons.h"

namespace elui {

namespace {
QString docLink(const QString& file, const QString& text) {
    const QString path = QDir(QStringLiteral(ELASTIC_LAB_SOURCE_DIR)).filePath(file);
    return QStringLiteral("<a href='%1'>%2</a>").arg(QUrl::fromLocalFile(path).toString(), text.toHtmlEscaped());
}

// A figure Help states, marked as a lesson answer is (ui/lessons.h) so that test_lessons
// measures it again with the same code (ui/lesson_measures.h: helpMeasures) and compares.
QString figure(const char* key, const char* value) {
    return QStringLiteral("<span class=\"answer\" data-key=\"%1\" data-tol=\"0.03\">%2</span>")
        .arg(QLatin1String(key), QLatin1String(value));
}

// What each integrator means for a class, beyond its one-line description (HTML).
QString integratorNote(const QString& name) {
    if (name == QLatin1String("euler"))
        return QObject::tr("Cheapest and least stable: on an undamped spring it gains energy at every DT. "
                           "On the two-layer ring it holds for 2 s up to DT %1 s (measured).")
            .arg(figure("limit-euler", "0.0086"));
    if (name == QLatin1String("midpoint"))
        return QObject::tr("Two force evaluations per step, second order; on the two-layer ring it holds for "
                           "2 s up to DT %1 s (measured), so it fails at the thesis's 0.03.")
            .arg(figure("limit-midpoint", "0.0108"));
    if (name == QLatin1String("rk4"))
        return QObject::tr("Four evaluations, fourth order; stable up to h·ω ≈ 2.8: on the two-layer ring it "
                           "holds for 2 s up to DT %1 s (measured), so it fails at the thesis's 0.03 and 0.3.")
            .arg(figure("limit-rk4", "0.0149"));
    if (name == QLatin1String("symplectic-euler"))
        return QObject::tr("Same cost as Euler, but energy stays bounded on an undamped spring (h·ω &lt; 2).");
    if (name == QLatin1String("verlet"))
        return QObject::tr("Velocity Verlet: time-reversible, good long-run energy behaviour. Second order "
                           "without damping; with the dampers on (every scene here) its damping sees the "
                           "half-step velocity and it is first order: the fitted order on the damped spring "
                           "is %1 (measured).")
            .arg(figure("order-verlet-damped", "1.02"));
    if (name == QLatin1String("yoshida4"))
        return QObject::tr("Three Verlet substeps (the middle one backwards): fourth order, and energy stays "
                           "bounded like Verlet's; stable up to h·ω ≈ 1.57 on an undamped spring.");
    if (name == QLatin1String("yoshida8"))
        return QObject::tr("Fifteen Verlet substeps: eighth order for undamped bodies, the error reaches "
                           "round-off at moderate steps; 16 force evaluations a step.");
    if (name == QLatin1String("rk45"))
        return QObject::tr("Chooses its own step to meet a tolerance; the readout shows its error estimate.");
    if (name == QLatin1String("implicit-euler"))
        return QObject::tr("Stable at any DT (it damps instead of blowing up): the one to use for DT 0.3.");
    if (name == QLatin1String("cvode-bdf"))
        return QObject::tr("A production stiff solver (SUNDIALS): wins where stiffness is damping (overdamped "
                           "springs), not where it is fast oscillation, which it must still follow.");
    if (name == QLatin1String("cvode-adams"))
        return QObject::tr("A production non-stiff solver (SUNDIALS): high order, few force evaluations per step.");
    if (name == QLatin1String("xpbd"))
        return QObject::tr("The game-physics way (Jolt, PhysX): stable at DT 1/60 on stiff springs, but it removes "
                           "energy the body never lost; more substeps, less loss.");
    return {};
}
}  // namespace

QString HelpDialog::html() {
    QString h;
    h += QObject::tr("<h2>Elastic Lab</h2><p>A two-layer elastic body: particles joined by springs, with gas "
                     "inside each closed layer. Drag the body with the mouse; change any parameter while it "
                     "runs.</p>");
    h += QObject::tr(
        "<h3>The model</h3><ul>"
        "<li><b>Particles</b> carry mass; gravity pulls along −y.</li>"
        "<li><b>Springs</b> (Hooke + damping): <i>structural</i> springs along each layer (KS, KD), "
        "<i>radius</i> springs between paired inner and outer particles and <i>shear</i> springs across "
        "them (RKS, RKD).</li>"
        "<li><b>Gas</b>: each closed layer encloses gas with P = nRT / V, pushing outward on every edge "
        "(2D) or face (3D). V is the exact area or volume.</li>"
        "<li><b>Mouse spring</b> (MKS, MKD) from the pointer to the grabbed particle.</li>"
        "<li><b>Contact</b> is a smooth force inside the equations of motion: a particle that sinks a "
        "depth d into a wall is pushed back by k d³ (contact energy k d⁴/4), damped so that one hitting "
        "at contact_speed rebounds with the restitution e, with smooth Coulomb friction, and a barrier of "
        "the same kind keeps the inner layer inside the outer one. contact = projection restores the "
        "thesis program instead, which puts a particle back and reverses its normal speed after each "
        "step.</li>"
        "<li><b>Resolution</b> (Scene dock): with scaling = physical the masses and spring constants "
        "hold at the scene's default mesh, and a finer mesh keeps the body's totals (layer mass, "
        "material stiffness), so it is the same body, only finer; scaling = thesis makes them per "
        "particle and per spring at every mesh. A finer body has faster modes and needs a smaller DT: "
        "the window offers one when a rebuild needs it.</li></ul>"
        "<p>The plots show the energy book: kinetic + spring + gravity + gas + contact is the total; "
        "what damping and contact take out is 'removed'. For an exact integrator, total + removed − "
        "work by the mouse stays constant; the readout's <i>energy drift</i> is how far it is off.</p>"
        "<p>View → <b>Energy bars</b> shows the same book as bars, one per term, in the plot's colours, "
        "with the drift last. View → <b>P–V diagram</b> shows each gas layer's pressure against its "
        "volume: the trail lies on the isotherm P = nRT / V, drawn dashed.</p>");
    h += QObject::tr("<h3>Integrators</h3><table border=1 cellspacing=0 cellpadding=4>"
                     "<tr><th>name</th><th>order</th><th>what it does</th><th>in class</th></tr>");
    for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
        const QString name = toQString(info.name);
        h += QStringLiteral("<tr><td><b>%1</b></td><td align=center>%2</td><td>%3</td><td>%4</td></tr>")
                 .arg(name)
                 .arg(name == QLatin1String("verlet") ? QObject::tr("2 (1 damped)") : QString::number(info.order))
                 .arg(toQString(info.description).toHtmlEscaped(), integratorNote(name));
    }
    h += QStringLiteral("</table>");
    h += QObject::tr("<h3>Presets</h3><ul>");
    for (const Preset& p : teachingPresets() + stabilityPresets())
        h += QStringLiteral("<li><b>%1</b>: %2</li>").arg(p.title.toHtmlEscaped(), p.description.toHtmlEscaped());
    h += QStringLiteral("</ul>");
    h += QObject::tr("<p><b>Lessons</b> menu (or Help → Experiments): %1 guided experiments, each set up in one "
                     "click, with what to change, what to look at and the answer measured with elastic-lab-cli; "
                     "the Lesson dock shows what each answer expects beside what your run gives.</p>")
             .arg(lessons().size());
    h += QObject::tr("<h3>Mouse</h3><ul><li>Left-drag on the body: grab the nearest outer particle and pull "
                     "it.</li><li>Left-drag elsewhere, or Shift+left-drag (3D): orbit. Right- or middle-drag: pan. Wheel: zoom. "
                     "View → Reset view.</li></ul>");
    h += QObject::tr("<h3>More</h3><ul>");
    h += QStringLiteral("<li>%1</li>").arg(docLink(QStringLiteral("docs/gui.md"), QObject::tr("The GUI (docs/gui.md)")));
    h += QStringLiteral("<li>%1</li>")
             .arg(docLink(QStringLiteral("docs/architecture.md"), QObject::tr("Architecture (docs/architecture.md)")));
    h += QStringLiteral("<li>%1</li>").arg(docLink(QStringLiteral("README.md"), QObject::tr("README")));
    h += QStringLiteral("</ul>");
    return h;
}

HelpDialog::HelpDialog(QWidget* parent) : QDialog(parent) {
    setWindowTitle(tr("Elastic Lab help"));
    resize(760, 680);
    auto* layout = new QVBoxLayout(this);
    auto* browser = new QTextBrowser(this);
    browser->setOpenExternalLinks(true);
    browser->setHtml(html());
    layout->addWidget(browser);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

}  // namespace elui
