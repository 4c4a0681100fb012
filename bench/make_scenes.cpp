// Writes the preview's scene families (tests/support/scene_families.h, tests/support/closed_form_scenes.h) at the
// sizes the preview issue names, for bench_preview and the command line:
//   bench_make_scenes DIR
// office-135 (15 x 9 ceiling lights), office-100 (10 x 10), lights-1000 (40 x 25 in a 60 x 36 m
// hall), lights-10000 (125 x 80 in a 250 x 160 m floor: the application's many-light case), closed-sphere-0.8 (a cap of ~6,000 emitter triangles), closed-room-{0.5,0.7,0.9} and
// emitters-10k (a ceiling panel of 10,082 emitter triangles in the 0.7 room), closed-sphere-1m
// (the sphere at 1,000,000 triangles: a large model), and issue 21's closed spheres
// closed-sphere-{0.5,0.6,0.7,0.8,0.9}-32k (32,000 triangles, a cap of 5,440 emitting, 96x96),
// whose exact radiance goes to DIR/closed-spheres.txt and, as a constant image, to NAME.ref.exr. Albedo 0.5 and 0.8 were used to decide
// changes to ir and mir, 0.6, 0.7 and 0.9 were kept out (bench/make_families.py).

#include "closed_form_scenes.h"
#include "scene_families.h"

#include "core/image/exr_io.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

using namespace lucerna;
using namespace lucerna::test;

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: bench_make_scenes DIR\n");
        return 2;
    }
    const std::string dir = argv[1];
    std::filesystem::create_directories(dir);
    const auto write = [&](const std::string& name, const std::string& json) {
        std::ofstream out(dir + "/" + name + ".json");
        out << json;
        if (!out) {
            std::fprintf(stderr, "bench_make_scenes: cannot write %s/%s.json\n", dir.c_str(), name.c_str());
            std::exit(1);
        }
        std::printf("%s/%s.json\n", dir.c_str(), name.c_str());
    };
    write("office-135", officeJson(15, 9, 640, 480));
    write("office-100", officeJson(10, 10, 640, 480));
    write("lights-1000", officeJson(40, 25, 640, 480, 40.0, 60.0, 36.0));
    write("lights-10000", officeJson(125, 80, 640, 480, 40.0, 250.0, 160.0));
    SphereWithEmittingCap sphere;
    sphere.rho = 0.8;
    sphere.rings = 96;
    sphere.segments = 192;
    sphere.resolution = 96;
    write("closed-sphere-0.8", sphere.json());
    std::printf("closed-sphere-0.8 exact radiance %.6f\n", sphere.expectedRadiance());
    SphereWithEmittingCap million;  // ~1,000,000 triangles, a sixth of them emitting
    million.rho = 0.8;
    million.rings = 500;
    million.segments = 1000;
    million.resolution = 96;
    write("closed-sphere-1m", million.json());
    for (const char* a : {"0.5", "0.7", "0.9"})
        write(std::string("closed-room-") + a, closedRoomJson(std::stod(a), 4, 640, 480));
    write("emitters-10k", closedRoomJson(0.7, 71, 640, 480));
    std::ofstream exact(dir + "/closed-spheres.txt");
    for (const char* a : {"0.5", "0.6", "0.7", "0.8", "0.9"}) {
        SphereWithEmittingCap s;
        s.rho = std::stod(a);
        s.rings = 100;
        s.segments = 160;
        s.resolution = 96;
        const std::string name = std::string("closed-sphere-") + a + "-32k";
        write(name, s.json());
        exact << name << " " << s.expectedRadiance() << "\n";
        // Its reference: the exact radiance in every pixel (the camera sits inside the sphere).
        Image reference(s.resolution, s.resolution);
        const float L = float(s.expectedRadiance());
        for (Rgb& p : reference.pixels) p = Rgb(L, L, L);
        writeExr(dir + "/" + name + ".ref.exr", reference);
    }
    if (!exact) {
        std::fprintf(stderr, "bench_make_scenes: cannot write %s/closed-spheres.txt\n", dir.c_str());
        return 1;
    }
    return 0;
}
