#pragma once
// The arrangement tool (issue 19, as DIALux's and Relux's field arrangement): a rectangular field
// of identical lights over a rectangle of the plan (x, z), hung below the ceiling, added in one
// undo step and gathered in a named group.
//
// - By count: columns x rows lights at the centres of the cells of the rectangle cut into that
//   many equal cells (columns along x, rows along z): x_i = x0 + (i + 1/2) (x1 - x0) / columns.
// - By spacing (metres): along each side as many lights as fit at that spacing,
//   n = floor(side / spacing) and at least one, spaced exactly so and centred on the rectangle;
//   where the spacing divides the side this is the field by count of n.
// - Height: every light at y = ceiling - suspension, the ceiling a height in the scene's unit
//   (by default the highest surface over the rectangle's centre) and the suspension in metres
//   below it (through meters_per_unit).

#include "core/scene/scene.h"

#include <string>
#include <vector>

namespace lucerna {

class Document;

// A field is at most this many lights (100 x 100: the largest field measured, README).
inline constexpr int kMaxFieldLights = 10000;

struct FieldArrangement {
    double x0 = 0, z0 = 0, x1 = 1, z1 = 1;  // the rectangle's corners in plan, scene units (any order)
    bool bySpacing = false;
    int columns = 1, rows = 1;              // by count: along x, along z
    double spacingXm = 1, spacingZm = 1;    // by spacing: metres along x, along z
    double ceilingY = 3;                    // the ceiling's height, scene units
    double suspensionM = 0;                 // metres below the ceiling
};

// The positions, row by row (rows along z), each row along x.
struct FieldLayout {
    int columns = 0, rows = 0;
    std::vector<V3d> positions;
};

// Throws std::invalid_argument with a one-line reason: a rectangle without area, a count below
// one, a spacing that is not positive, more than kMaxFieldLights lights, a value not finite.
FieldLayout layoutField(const FieldArrangement& field, double metersPerUnit);

// The highest surface of the scene over the plan point (x, z), in scene units: the ceiling for a
// room; the top of the scene's bounds where nothing lies over the point.
double ceilingAbove(const Scene& scene, double x, double z);

// The field's lights: copies of `prototype` (its type, aim, output, luminaire file, switched on)
// at the layout's positions, in `group`, named GROUP-ROW-COLUMN (from 1; a name the scene already
// uses gets a suffix -2, -3, ... as Duplicate does).
std::vector<Light> fieldLights(const Scene& scene, const FieldLayout& layout, const Light& prototype,
                               const std::string& group);

// A group name no light of the scene uses: base, or base-2, base-3, ...
std::string unusedGroupName(const Scene& scene, const std::string& base);

// Adds the field to the document as one undo step (its lights after the scene's others) and
// returns how many lights it added. Throws std::invalid_argument (layoutField, an empty group).
int arrangeField(Document& doc, const FieldArrangement& field, const Light& prototype, const std::string& group);

}  // namespace lucerna
