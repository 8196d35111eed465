#include "gl/framebuffer.h"

#include <string>

namespace tidepool::gl {
namespace {
const char* statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT: return "incomplete attachment";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT: return "missing attachment";
    case GL_FRAMEBUFFER_UNSUPPORTED: return "unsupported format combination";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE: return "multisample mismatch";
    default: return "incomplete";
  }
}
}  // namespace

Framebuffer::Framebuffer(std::initializer_list<const Texture2D*> colors, const Texture2D* depth) {
  m_handle = Handle<Kind::Framebuffer>::generate();
  glBindFramebuffer(GL_FRAMEBUFFER, id());
  std::vector<GLenum> drawBuffers;
  for (const Texture2D* c : colors) {
    const GLenum attachment = GL_COLOR_ATTACHMENT0 + GLenum(drawBuffers.size());
    glFramebufferTexture2D(GL_FRAMEBUFFER, attachment, GL_TEXTURE_2D, c->id(), 0);
    drawBuffers.push_back(attachment);
    m_width = c->width();
    m_height = c->height();
  }
  if (depth) {
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth->id(), 0);
    m_width = depth->width();
    m_height = depth->height();
  }
  glDrawBuffers(GLsizei(drawBuffers.size()), drawBuffers.data());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE)
    throw GlError(std::string("framebuffer is not complete: ") + statusName(status));
}

void Framebuffer::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, id());
  glViewport(0, 0, m_width, m_height);
}

VertexArray VertexArray::create() {
  VertexArray v;
  v.m_handle = Handle<Kind::VertexArray>::generate();
  return v;
}

Query Query::create() {
  Query q;
  q.m_handle = Handle<Kind::Query>::generate();
  return q;
}

}  // namespace tidepool::gl
