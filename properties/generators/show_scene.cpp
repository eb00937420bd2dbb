// A failing property's scene as RapidCheck prints it: .tri text.
#include <rast/property_generators.h>
#include <rast/tri_format.h>

#include <stdexcept>

namespace rast {

void showValue(const Scene& scene, std::ostream& os) {
    os << '\n';
    try {
        write_tri(os, scene);
    } catch (const std::invalid_argument& e) {
        // Not writable as .tri (a generator's scene is always valid input, a hand-made one may not be).
        os << "(a scene .tri cannot hold: " << e.what() << ")";
    }
}

}  // namespace rast
