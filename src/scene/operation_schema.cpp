// The keys of a chain of operations (docs/chains.md): `operations`, each
// with its own sections of the case's keys.
#include "schema_keys.h"

namespace anvil::scene::schema_keys {

std::vector<KeySpec> operation_keys() {
  using T = KeyType;
  std::vector<KeySpec> keys = {
      key("operations", T::list,
          "the operations of a forging run in order, each from the part the one before left (docs/chains.md); "
          "absent: the case is one operation"),
      required(key("operations[].name", T::name, "the operation's name: its output folder is NN-name")),
      with_default(choices(key("operations[].type", T::string,
                               "forge: dies move; transfer, dwell, cool: heat alone (nothing moves; a transfer "
                               "or dwell lies on its fixed dies); trim: the flash cut off"),
                           {"forge", "transfer", "dwell", "cool", "trim"}),
                   "forge"),
      key("operations[].place", T::map,
          "where the part goes before the operation: flipped, turned, moved, then rested on the lower die"),
      with_default(key("operations[].place.flip", T::boolean,
                       "turn the part upside down (half a turn about a horizontal axis through its centre)"),
                   "false"),
      with_default(key("operations[].place.turn", T::number, "a turn about the press axis z", "deg"), "0"),
      with_default(key("operations[].place.move", T::vector3, "a translation", "mm"), "[0, 0, 0]"),
      with_default(key("operations[].place.rest", T::boolean,
                       "lower the part along z until it rests on the lowest die of the operation"),
                   "false"),
      key("operations[].trim", T::map, "type trim: the cut; the part inside it is kept"),
      range(key("operations[].trim.line", T::numbers,
                "a closed trim line in the plane normal to z, extruded along z: x1, y1, x2, y2, ... (at least "
                "three points, the whole part's line even for a symmetry model)",
                "mm"),
            -1e6, 1e6),
      key("operations[].trim.stl", T::string, "a closed STL surface, outward normals: the part inside it is kept"),
      range(key("time.stop.temperature", T::number, "heat alone: stop when the bodies' hottest node has cooled to this",
                "°C"),
            kAbsoluteZero, kHottest, true),
  };
  for (const auto& [section, type] : kOperationSections)
    keys.push_back(alias(key(std::string("operations[].") + section, type,
                             std::string("the operation's own '") + section + "' (see it above)"),
                         section));
  return keys;
}

} // namespace anvil::scene::schema_keys
