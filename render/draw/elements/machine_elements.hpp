// The machine elements of the chapter's drawings (Figs 1.17, 1.18 and section 1.12): springs, dashpots, wheels, boxes, hatched floors and walls, road profiles.
// Drawn in world units through a WorldView, so they stretch and move with the
// solution; no physics here. The *_points functions are the geometry (pure,
// tested), the draw_* functions stroke it.
#pragma once
#include <span>
#include <vector>

#include "render/draw/elements/shapes.hpp"

namespace vibra::render {

/// A spring drawn as a zigzag: straight leads at both ends, then `coils`
/// full zigzags across a band of `width` (world units). The number of coils
/// is fixed, so the zigzag stretches and compresses with the distance.
struct SpringShape {
  int coils = 8;
  double width = 0.12;  ///< world units, across the axis
  double lead = 0.08;   ///< straight part at each end (at most a quarter of the length)
};
std::vector<Point> spring_points(const Point& from, const Point& to, const SpringShape&);
void draw_spring(Canvas&, const WorldView&, const Point& from, const Point& to, const SpringShape&, const Stroke&);

/// A dashpot (damper): a cylinder fixed to `from`, open toward `to`, and a
/// piston on a rod of fixed length from `to`, so the piston slides in the
/// cylinder as the distance changes.
struct DashpotShape {
  double width = 0.12;      ///< cylinder width, world units
  double cylinder = 0.30;   ///< cylinder length as a fraction of the rest distance
  double rest_length = 1;   ///< distance at which the piston sits mid-cylinder
};
struct DashpotGeometry {
  Point rod_from_start, rod_from_end;  ///< rod from `from` to the cylinder's bottom
  std::vector<Point> cylinder;         ///< open U: mouth corner, bottom corners, mouth corner
  Point piston_a, piston_b;            ///< the piston plate, across the axis
  Point rod_to_start, rod_to_end;      ///< rod from the piston to `to`
};
DashpotGeometry dashpot_geometry(const Point& from, const Point& to, const DashpotShape&);
void draw_dashpot(Canvas&, const WorldView&, const Point& from, const Point& to, const DashpotShape&, const Stroke&);

/// A wheel of `radius` at `center` with a hub and spokes turned by `angle`
/// (radians, counter-clockwise), so rolling is visible.
void draw_wheel(Canvas&, const WorldView&, const Point& center, double radius, double angle, const Color& fill,
                const Stroke&);

/// An axis-aligned box from `low` (lower left) to `high` (upper right), filled and outlined.
void draw_box(Canvas&, const WorldView&, const Point& low, const Point& high, const Color& fill, const Stroke&);

/// A rigid surface from `a` to `b`, a thick line hatched on the side of
/// `outside` (a unit direction, world units): a floor is hatched below
/// (outside = (0, -1)), a wall to the left (outside = (-1, 0)).
void draw_hatched_surface(Canvas&, const WorldView&, const Point& a, const Point& b, const Point& outside,
                          const Stroke&);

}  // namespace vibra::render
