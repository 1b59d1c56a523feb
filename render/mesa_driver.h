#pragma once

namespace plywood::render {

// Snapshots and pictures are drawn by Mesa's llvmpipe through OSMesa. GALLIUM_DRIVER picks another
// rasteriser: softpipe drew other pixels (snapshot.png differed from the same seed's without a
// word), swrast or an unknown name crashed Mesa (SIGSEGV, exit 139). Unset, empty or llvmpipe
// passes. Called once before a command runs, so a sweep's runs, which inherit it, never meet it.
// @throws std::invalid_argument "GALLIUM_DRIVER: NAME: ..." naming the fix.
void RequireTheReproducibleMesaDriver();

}  // namespace plywood::render
