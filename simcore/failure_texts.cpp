#include "simcore/failure_texts.h"

#include <sstream>

namespace simcore::failure_text {

std::string nonFinite() {
    return "the state became non-finite (NaN or infinity): the step is far too large for these forces";
}

std::string runawayVelocity(double fastest) {
    std::ostringstream why;
    why << "runaway velocity: a particle moves " << fastest << " m/s, farther than the whole box in one step";
    return why.str();
}

std::string runawayEnergy(double held, double budget, double factor) {
    std::ostringstream why;
    why << "runaway energy: kinetic + elastic energy " << held << " J exceeds " << budget << " J (" << factor
        << " x the body's energy scale)";
    return why.str();
}

std::string layerLost(std::optional<std::size_t> body, Layer layer, int dimension, double volume, double rest) {
    std::ostringstream why;
    if (body) why << "body " << *body << ": ";
    why << "the " << layerName(layer) << " layer " << (volume <= 0.0 ? "turned inside out" : "collapsed") << " (its "
        << (dimension == 2 ? "area" : "volume") << " is " << volume << ", rest " << rest << ")";
    return why.str();
}

std::string layersCrossed(std::size_t a, std::size_t b, double h) {
    std::ostringstream why;
    if (a == b)
        why << "body " << a << "'s outer layer passed through itself";
    else
        why << "bodies " << a << " and " << b << " intersect (their outer layers crossed)";
    why << " in a step of " << h << " s: the step is too large for this impact (a smaller dt, or an adaptive "
        << "integrator, which halves such a step)";
    return why.str();
}

std::string floatNotFinite(std::size_t particle) {
    return "the state is no longer finite (particle " + std::to_string(particle) + ")";
}

std::string floatReachedWall(std::size_t particle) {
    return "particle " + std::to_string(particle) + " reached a wall: the float path has no contact (use precision double)";
}

}  // namespace simcore::failure_text
