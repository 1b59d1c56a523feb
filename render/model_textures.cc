#include "render/model_textures.h"

#include <cstdint>
#include <span>
#include <vector>

#include "render/offscreen_context.h"
#include "render/texture_mipmaps.h"

#if PLYWOOD_HAS_OSMESA
#include <GL/gl.h>
#endif

namespace plywood::render {

#if PLYWOOD_HAS_OSMESA

namespace {

struct GlTextureFunctions {
  void (*active_texture)(GLenum) = nullptr;
  void (*gen_textures)(GLsizei, GLuint*) = nullptr;
  void (*bind_texture)(GLenum, GLuint) = nullptr;
  void (*tex_parameteri)(GLenum, GLenum, GLint) = nullptr;
  void (*tex_geni)(GLenum, GLenum, GLint) = nullptr;
  void (*tex_genfv)(GLenum, GLenum, const GLfloat*) = nullptr;
  void (*tex_image_2d)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum,
                       const void*) = nullptr;
  void (*pixel_storei)(GLenum, GLint) = nullptr;
  bool complete() const {
    return active_texture && gen_textures && bind_texture && tex_parameteri && tex_geni &&
           tex_genfv && tex_image_2d && pixel_storei;
  }
};

template <typename F>
void Find(F* f, const char* name) {
  *f = reinterpret_cast<F>(GlProcAddress(name));
}

const GlTextureFunctions& Functions() {
  static const GlTextureFunctions f = [] {
    GlTextureFunctions g;
    Find(&g.active_texture, "glActiveTexture");
    Find(&g.gen_textures, "glGenTextures");
    Find(&g.bind_texture, "glBindTexture");
    Find(&g.tex_parameteri, "glTexParameteri");
    Find(&g.tex_geni, "glTexGeni");
    Find(&g.tex_genfv, "glTexGenfv");
    Find(&g.tex_image_2d, "glTexImage2D");
    Find(&g.pixel_storei, "glPixelStorei");
    return g;
  }();
  return f;
}

}  // namespace

bool CanUploadMipmapChains(const mjModel* m) {
  if (m->ntex < 1 || m->ntex > mjMAXTEXTURE) return false;
  for (int t = 0; t < m->ntex; ++t) {
    if (m->tex_type[t] != mjTEXTURE_2D || !IsPowerOfTwo(m->tex_width[t]) ||
        !IsPowerOfTwo(m->tex_height[t])) {
      return false;
    }
  }
  return Functions().complete();
}

void MakeContextWithMipmapChains(mjModel* m, mjrContext* con, int fontscale) {
  if (!CanUploadMipmapChains(m)) {
    mjr_makeContext(m, con, fontscale);
    return;
  }
  const int ntex = m->ntex;
  m->ntex = 0;
  mjr_makeContext(m, con, fontscale);
  m->ntex = ntex;
  const GlTextureFunctions& gl = Functions();
  con->ntexture = ntex;
  gl.gen_textures(ntex, con->texture);
  for (int t = 0; t < ntex; ++t) {
    con->textureType[t] = m->tex_type[t];
    // What mjr_uploadTexture sets for a 2-D texture: its parameters, and on texture unit 0 the
    // object-linear texture coordinate generation the renderer's texuniform planes rely on.
    gl.active_texture(GL_TEXTURE0);
    gl.bind_texture(GL_TEXTURE_2D, con->texture[t]);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_R, GL_REPEAT);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    gl.tex_parameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    const GLfloat s_plane[4] = {1.0f, 0.0f, 0.0f, 0.0f};
    const GLfloat t_plane[4] = {0.0f, 1.0f, 0.0f, 0.0f};
    gl.tex_genfv(GL_S, GL_OBJECT_PLANE, s_plane);
    gl.tex_genfv(GL_T, GL_OBJECT_PLANE, t_plane);
    gl.tex_geni(GL_S, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);
    gl.tex_geni(GL_T, GL_TEXTURE_GEN_MODE, GL_OBJECT_LINEAR);

    const int width = m->tex_width[t], height = m->tex_height[t];
    const std::span<const std::uint8_t> rgb(m->tex_rgb + m->tex_adr[t],
                                            static_cast<std::size_t>(width) * height * 3);
    gl.pixel_storei(GL_UNPACK_ALIGNMENT, 1);
    gl.tex_image_2d(GL_TEXTURE_2D, 0, GL_RGB, width, height, 0, GL_RGB, GL_UNSIGNED_BYTE,
                    rgb.data());
    const std::vector<std::vector<std::uint8_t>> levels = MipmapChain(rgb, width, height);
    int w = width, h = height;
    for (std::size_t level = 0; level < levels.size(); ++level) {
      w = w > 1 ? w / 2 : 1;
      h = h > 1 ? h / 2 : 1;
      gl.tex_image_2d(GL_TEXTURE_2D, static_cast<GLint>(level + 1), GL_RGB, w, h, 0, GL_RGB,
                      GL_UNSIGNED_BYTE, levels[level].data());
    }
  }
}

#else  // !PLYWOOD_HAS_OSMESA

bool CanUploadMipmapChains(const mjModel*) { return false; }

void MakeContextWithMipmapChains(mjModel* m, mjrContext* con, int fontscale) {
  mjr_makeContext(m, con, fontscale);
}

#endif

}  // namespace plywood::render
