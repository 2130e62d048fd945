#pragma once
// hierarchical-volume's own counters (thesis section 4.3): the (volume, tile) pairs with a
// surface that some triangle of the volume overlaps on screen, by how the tile was classified.
#include "core/stats.h"

namespace penumbra {

inline constexpr CounterSpec kTilesLit{
    "tiles_lit", "(volume, tile) pairs no volume triangle crosses, outside the volume"};
inline constexpr CounterSpec kTilesShadowed{
    "tiles_shadowed", "(volume, tile) pairs no volume triangle crosses, inside the volume"};
inline constexpr CounterSpec kTilesBoundary{
    "tiles_boundary", "(volume, tile) pairs a volume triangle crosses: drawn per pixel"};

}  // namespace penumbra
