#pragma once

#include <mujoco/mujoco.h>

namespace plywood::render {

// Whether MakeContextWithMipmapChains uploads `m`'s textures itself: all of them 2-D with
// power-of-two sides (at least one), and the GL functions it needs found.
bool CanUploadMipmapChains(const mjModel* m);

// mjr_makeContext(m, con, fontscale) on the current GL context, except that when
// CanUploadMipmapChains(m) the textures are uploaded here, every mipmap level from MipmapChain,
// instead of by MuJoCo's mjr_uploadTexture, whose glGenerateMipmap makes llvmpipe compile a blit
// shader in every process (~0.43G instructions, most of a snapshot's set-up). Same texels in every
// level, same texture parameters (GL_RGB; repeat in s, t and r; trilinear minification, linear
// magnification), unpack alignment 1 and texture unit 0's object-linear s and t generation (which
// texuniform materials rely on) as MuJoCo 2.2.2 leaves them (model_textures_test.cc reads both
// back), so a frame drawn with either is the same. `m->ntex` is 0 during mjr_makeContext
// and restored before this returns.
void MakeContextWithMipmapChains(mjModel* m, mjrContext* con, int fontscale);

}  // namespace plywood::render
