#include "render/model_textures.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>

#include "render/offscreen_context.h"
#include "render/texture_mipmaps.h"
#include "sim/world/mujoco_handles.h"

#if PLYWOOD_HAS_OSMESA
#include <GL/gl.h>
#endif

namespace plywood::render {
namespace {

TEST(TextureMipmapsTest, LevelsHalveEachSideDownToOneTexel) {
  const std::vector<std::uint8_t> rgb(16 * 4 * 3, 7);
  const auto levels = MipmapChain(rgb, 16, 4);
  ASSERT_EQ(levels.size(), 4u);  // 8 x 2, 4 x 1, 2 x 1, 1 x 1
  EXPECT_EQ(levels[0].size(), 8u * 2 * 3);
  EXPECT_EQ(levels[1].size(), 4u * 1 * 3);
  EXPECT_EQ(levels[2].size(), 2u * 1 * 3);
  EXPECT_EQ(levels[3].size(), 1u * 1 * 3);
  for (const auto& level : levels) {
    for (std::uint8_t v : level) EXPECT_EQ(v, 7);  // a flat texture stays flat
  }
  EXPECT_TRUE(MipmapChain(std::vector<std::uint8_t>(3, 9), 1, 1).empty());
}

TEST(TextureMipmapsTest, RoundsTheLerpOfTheLerps) {
  // One channel: Half(Half(0, 1), Half(0, 0)) = Half(1, 0) = 1 (Half rounds 0.5 up, from p's
  // side): not the box filter's (0 + 1 + 0 + 0 + 2) / 4 = 0.
  const std::vector<std::uint8_t> rgb{0, 0, 0, 1, 1, 1, 0, 0, 0, 0, 0, 0};
  const auto levels = MipmapChain(rgb, 2, 2);
  ASSERT_EQ(levels.size(), 1u);
  EXPECT_EQ(levels[0], (std::vector<std::uint8_t>{1, 1, 1}));
}

TEST(TextureMipmapsTest, RejectsSidesThatAreNoPowerOfTwoAndWrongSizes) {
  EXPECT_THROW(MipmapChain(std::vector<std::uint8_t>(3 * 3 * 3), 3, 3), std::invalid_argument);
  EXPECT_THROW(MipmapChain(std::vector<std::uint8_t>(5), 2, 2), std::invalid_argument);
  EXPECT_FALSE(IsPowerOfTwo(0));
  EXPECT_FALSE(IsPowerOfTwo(6));
  EXPECT_TRUE(IsPowerOfTwo(1));
  EXPECT_TRUE(IsPowerOfTwo(1024));
}

#if PLYWOOD_HAS_OSMESA

template <typename F>
F Gl(const char* name) {
  void* f = GlProcAddress(name);
  if (f == nullptr) throw std::runtime_error(std::string("no GL function ") + name);
  return reinterpret_cast<F>(f);
}

struct Texture {
  std::vector<std::vector<std::uint8_t>> levels;  // level 0 first, tightly packed RGB
  std::vector<GLint> parameters;
  std::vector<GLint> formats;
};

// Texture unit 0's coordinate generation (per unit, not per texture): mode and object planes of
// s, t, r and q.
std::vector<GLfloat> TexGenState() {
  const auto active = Gl<void (*)(GLenum)>("glActiveTexture");
  const auto geni = Gl<void (*)(GLenum, GLenum, GLint*)>("glGetTexGeniv");
  const auto genf = Gl<void (*)(GLenum, GLenum, GLfloat*)>("glGetTexGenfv");
  active(GL_TEXTURE0);
  std::vector<GLfloat> state;
  for (GLenum c : {GL_S, GL_T, GL_R, GL_Q}) {
    GLint mode = -1;
    geni(c, GL_TEXTURE_GEN_MODE, &mode);
    state.push_back(static_cast<GLfloat>(mode));
    GLfloat plane[4] = {-7, -7, -7, -7};
    genf(c, GL_OBJECT_PLANE, plane);
    state.insert(state.end(), plane, plane + 4);
  }
  return state;
}

Texture ReadBack(GLuint name) {
  const auto bind = Gl<void (*)(GLenum, GLuint)>("glBindTexture");
  const auto level_parameter =
      Gl<void (*)(GLenum, GLint, GLenum, GLint*)>("glGetTexLevelParameteriv");
  const auto parameter = Gl<void (*)(GLenum, GLenum, GLint*)>("glGetTexParameteriv");
  const auto get_image = Gl<void (*)(GLenum, GLint, GLenum, GLenum, void*)>("glGetTexImage");
  const auto pack = Gl<void (*)(GLenum, GLint)>("glPixelStorei");
  bind(GL_TEXTURE_2D, name);
  pack(GL_PACK_ALIGNMENT, 1);
  Texture t;
  for (GLenum p :
       {GL_TEXTURE_MIN_FILTER, GL_TEXTURE_MAG_FILTER, GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T,
        GL_TEXTURE_WRAP_R, GL_TEXTURE_BASE_LEVEL, GL_TEXTURE_MAX_LEVEL}) {
    GLint v = -1;
    parameter(GL_TEXTURE_2D, p, &v);
    t.parameters.push_back(v);
  }
  for (GLint level = 0;; ++level) {
    GLint w = 0, h = 0, format = 0;
    level_parameter(GL_TEXTURE_2D, level, GL_TEXTURE_WIDTH, &w);
    level_parameter(GL_TEXTURE_2D, level, GL_TEXTURE_HEIGHT, &h);
    if (w == 0 || h == 0) break;
    level_parameter(GL_TEXTURE_2D, level, GL_TEXTURE_INTERNAL_FORMAT, &format);
    t.formats.push_back(format);
    t.levels.emplace_back(static_cast<std::size_t>(w) * h * 3);
    get_image(GL_TEXTURE_2D, level, GL_RGB, GL_UNSIGNED_BYTE, t.levels.back().data());
  }
  return t;
}

TEST(TextureMipmapsTest, EqualsGlGenerateMipmap) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  OffscreenContext context(16, 16);
  const auto gen = Gl<void (*)(GLsizei, GLuint*)>("glGenTextures");
  const auto bind = Gl<void (*)(GLenum, GLuint)>("glBindTexture");
  const auto unpack = Gl<void (*)(GLenum, GLint)>("glPixelStorei");
  const auto image =
      Gl<void (*)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum, const void*)>(
          "glTexImage2D");
  const auto generate = Gl<void (*)(GLenum)>("glGenerateMipmap");
  std::mt19937 rng(17);
  const int sides[][2] = {{64, 64}, {128, 2}, {2, 128},  {1, 64},  {64, 1},
                          {1, 1},   {2, 2},   {256, 16}, {8, 512}, {512, 512}};
  for (const auto& [w, h] : sides) {
    std::vector<std::uint8_t> rgb(static_cast<std::size_t>(w) * h * 3);
    for (auto& v : rgb) v = static_cast<std::uint8_t>(rng());
    GLuint name = 0;
    gen(1, &name);
    bind(GL_TEXTURE_2D, name);
    unpack(GL_UNPACK_ALIGNMENT, 1);
    image(GL_TEXTURE_2D, 0, GL_RGB, w, h, 0, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    generate(GL_TEXTURE_2D);
    const Texture gl = ReadBack(name);
    const auto ours = MipmapChain(rgb, w, h);
    ASSERT_EQ(gl.levels.size(), ours.size() + 1) << w << " x " << h;
    EXPECT_EQ(gl.levels[0], rgb);
    for (std::size_t l = 0; l < ours.size(); ++l) {
      EXPECT_EQ(gl.levels[l + 1], ours[l]) << w << " x " << h << " level " << l + 1;
    }
  }
}

// Textures of every kind MuJoCo builds (checker with edge marks, gradient, random, from rgb
// values), of power-of-two sides, square and not.
constexpr char kTextured[] = R"(
<mujoco>
  <asset>
    <texture name="checker" type="2d" builtin="checker" rgb1="0.46 0.47 0.48" rgb2="0.40 0.41 0.42"
             width="64" height="64" mark="edge" markrgb="0.33 0.33 0.34"/>
    <texture name="noise" type="2d" builtin="flat" rgb1="0.2 0.6 0.3" mark="random"
             random="0.4" markrgb="0.9 0.1 0.5" width="32" height="128"/>
    <texture name="gradient" type="2d" builtin="gradient" rgb1="1 0 0" rgb2="0 0 1" width="16"
             height="8"/>
    <material name="floor" texture="checker" texrepeat="1 1" texuniform="true"/>
    <material name="noisy" texture="noise"/>
    <material name="graded" texture="gradient"/>
  </asset>
  <worldbody>
    <geom type="plane" size="3 3 0.05" material="floor"/>
    <geom type="box" pos="1 0 0.2" size="0.3 0.3 0.2" material="noisy"/>
    <geom type="box" pos="-1 0 0.2" size="0.3 0.3 0.2" material="graded"/>
  </worldbody>
</mujoco>)";

TEST(ModelTexturesTest, SameTexelsAndParametersAsMujocosUpload) {
  if (!OffscreenRenderingAvailable()) GTEST_SKIP() << "no offscreen OpenGL context here";
  const sim::MjModelPtr m = sim::LoadModelFromString(kTextured, "textured.xml");
  ASSERT_EQ(m->ntex, 3);
  ASSERT_TRUE(CanUploadMipmapChains(m.get()));
  std::vector<Texture> mujoco, ours;
  GLint mujoco_unpack = 0, ours_unpack = 0;
  std::vector<GLfloat> mujoco_texgen, ours_texgen;
  const auto get_integer = Gl<void (*)(GLenum, GLint*)>("glGetIntegerv");
  {
    OffscreenContext context(16, 16);
    mjrContext con;
    mjr_defaultContext(&con);
    mjr_makeContext(m.get(), &con, mjFONTSCALE_100);
    get_integer(GL_UNPACK_ALIGNMENT, &mujoco_unpack);
    mujoco_texgen = TexGenState();
    for (int t = 0; t < con.ntexture; ++t) mujoco.push_back(ReadBack(con.texture[t]));
    mjr_freeContext(&con);
  }
  {
    OffscreenContext context(16, 16);
    mjrContext con;
    mjr_defaultContext(&con);
    MakeContextWithMipmapChains(m.get(), &con, mjFONTSCALE_100);
    EXPECT_EQ(m->ntex, 3);
    get_integer(GL_UNPACK_ALIGNMENT, &ours_unpack);
    ours_texgen = TexGenState();
    ASSERT_EQ(con.ntexture, 3);
    for (int t = 0; t < con.ntexture; ++t) {
      EXPECT_EQ(con.textureType[t], mjTEXTURE_2D);
      ours.push_back(ReadBack(con.texture[t]));
    }
    mjr_freeContext(&con);
  }
  EXPECT_EQ(ours_unpack, mujoco_unpack);
  EXPECT_EQ(ours_texgen, mujoco_texgen);  // object-linear s and t, which texuniform needs
  ASSERT_EQ(ours.size(), mujoco.size());
  for (std::size_t t = 0; t < ours.size(); ++t) {
    EXPECT_EQ(ours[t].parameters, mujoco[t].parameters) << "texture " << t;
    EXPECT_EQ(ours[t].formats, mujoco[t].formats) << "texture " << t;
    ASSERT_EQ(ours[t].levels.size(), mujoco[t].levels.size()) << "texture " << t;
    for (std::size_t l = 0; l < ours[t].levels.size(); ++l) {
      EXPECT_EQ(ours[t].levels[l], mujoco[t].levels[l]) << "texture " << t << " level " << l;
    }
  }
}

TEST(ModelTexturesTest, OtherTexturesAreLeftToMujoco) {
  const sim::MjModelPtr cube = sim::LoadModelFromString(R"(
<mujoco>
  <asset><texture name="sky" type="skybox" builtin="gradient" rgb1="1 1 1" rgb2="0 0 0"
                  width="32" height="32"/></asset>
  <worldbody><geom type="sphere" size="0.1"/></worldbody>
</mujoco>)",
                                                        "sky.xml");
  EXPECT_FALSE(CanUploadMipmapChains(cube.get()));
  const sim::MjModelPtr odd = sim::LoadModelFromString(R"(
<mujoco>
  <asset><texture name="odd" type="2d" builtin="checker" rgb1="1 1 1" rgb2="0 0 0" width="48"
                  height="32"/></asset>
  <worldbody><geom type="sphere" size="0.1"/></worldbody>
</mujoco>)",
                                                       "odd.xml");
  EXPECT_FALSE(CanUploadMipmapChains(odd.get()));
  const sim::MjModelPtr none =
      sim::LoadModelFromString("<mujoco><worldbody/></mujoco>", "none.xml");
  EXPECT_FALSE(CanUploadMipmapChains(none.get()));
}

#endif

}  // namespace
}  // namespace plywood::render
