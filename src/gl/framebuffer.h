// Framebuffer objects and the small objects that go with drawing: vertex arrays and queries.
#pragma once

#include <initializer_list>
#include <vector>

#include "gl/handle.h"
#include "gl/texture.h"

namespace tidepool::gl {

class Framebuffer {
 public:
  Framebuffer() = default;
  // Colour attachments in order (GL_COLOR_ATTACHMENT0 + i), optional depth texture.
  Framebuffer(std::initializer_list<const Texture2D*> colors, const Texture2D* depth = nullptr);

  GLuint id() const { return m_handle.get(); }
  int width() const { return m_width; }
  int height() const { return m_height; }
  void bind() const;  // binds for drawing and sets the viewport to the attachments' size

 private:
  Handle<Kind::Framebuffer> m_handle;
  int m_width = 0, m_height = 0;
};

// An empty or attribute-less vertex array: our draws fetch from SSBOs by gl_VertexID.
class VertexArray {
 public:
  static VertexArray create();
  GLuint id() const { return m_handle.get(); }
  void bind() const { glBindVertexArray(id()); }

 private:
  Handle<Kind::VertexArray> m_handle;
};

class Query {
 public:
  static Query create();
  GLuint id() const { return m_handle.get(); }

 private:
  Handle<Kind::Query> m_handle;
};

}  // namespace tidepool::gl
