// The marks of the book's figures that --annotate NAME adds, and which command (render or plot) draws each.
#include "scenes/overlays/annotations.hpp"

#include "core/error.hpp"
#include "core/input/parameters.hpp"

namespace vibra::scenes {

const std::vector<AnnotationKind>& all_annotations() {
  static const std::vector<AnnotationKind> kinds = {
      {"geometry", "render", "the pendulum's unit vectors i_r and i_theta, its pivot (x0, y0) and length L (Fig 1.21)",
       "vibra render pendulum --annotate geometry --at 1 -o geometry.png"},
      {"mesh", "plot",
       "a dot at every step t_n, and the staggered scheme's v at the half steps t_n+1/2 (Fig 1.12)",
       "vibra plot undamped --set scheme=staggered --set steps_per_period=8 --set periods=2 --panels u,v "
       "--annotate mesh -o mesh.png"},
  };
  return kinds;
}

void check_annotation_name(const std::string& name, const std::string& command) {
  std::vector<std::string> names;
  std::string list;
  for (const AnnotationKind& kind : all_annotations()) {
    if (kind.name == name) {
      if (kind.command == command) return;
      throw UsageError("annotation '" + name + "' is drawn by vibra " + kind.command + ", not vibra " + command +
                       ": e.g. " + kind.example);
    }
    names.push_back(kind.name);
    list += (list.empty() ? "" : ", ") + kind.name + " (vibra " + kind.command + ")";
  }
  const std::string near = closest_match(name, names);
  throw UsageError("unknown annotation '" + name + "'" + (near.empty() ? "" : " (did you mean '" + near + "'?)") +
                   ": choose from " + list);
}

}  // namespace vibra::scenes
