#include "renderer.hpp"

#include <stdexcept>
#include <string>

namespace cosmems::viewer {
namespace {

constexpr const char* kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 view_projection;
out vec3 world_normal;
void main() {
  world_normal = normal;
  gl_Position = view_projection * vec4(position, 1.0);
}
)";

constexpr const char* kFragmentShader = R"(#version 330 core
in vec3 world_normal;
uniform vec3 colour;
uniform vec3 light;
out vec4 fragment;
void main() {
  float diffuse = max(dot(normalize(world_normal), light), 0.0);
  fragment = vec4(colour * (0.4 + 0.6 * diffuse), 1.0);
}
)";

GLuint Compile(GLenum kind, const char* source) {
  const GLuint shader = glCreateShader(kind);
  glShaderSource(shader, 1, &source, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    glGetShaderInfoLog(shader, sizeof(log), nullptr, log);
    glDeleteShader(shader);
    throw std::runtime_error(std::string("OpenGL: a shader did not compile: ") + log);
  }
  return shader;
}

}  // namespace

Renderer::Renderer() {
  const GLuint vertex = Compile(GL_VERTEX_SHADER, kVertexShader);
  const GLuint fragment = Compile(GL_FRAGMENT_SHADER, kFragmentShader);
  program_ = glCreateProgram();
  glAttachShader(program_, vertex);
  glAttachShader(program_, fragment);
  glLinkProgram(program_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(program_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[1024] = {};
    glGetProgramInfoLog(program_, sizeof(log), nullptr, log);
    glDeleteProgram(program_);
    throw std::runtime_error(std::string("OpenGL: the shaders did not link: ") + log);
  }
  view_projection_ = glGetUniformLocation(program_, "view_projection");
  colour_ = glGetUniformLocation(program_, "colour");
  light_ = glGetUniformLocation(program_, "light");
  glGenVertexArrays(1, &vertex_array_);
  glGenBuffers(1, &buffer_);
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
  constexpr GLsizei kStride = 6 * sizeof(float);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, kStride, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, kStride,
                        reinterpret_cast<const void*>(3 * sizeof(float)));
  glBindVertexArray(0);
}

Renderer::~Renderer() {
  glDeleteBuffers(1, &buffer_);
  glDeleteVertexArrays(1, &vertex_array_);
  glDeleteProgram(program_);
}

void Renderer::BeginScene(int window_width, int window_height, const Viewport& viewport,
                          const Eigen::Matrix4d& view_projection) {
  glViewport(0, 0, window_width, window_height);
  glClearColor(palette::kBackground.r, palette::kBackground.g, palette::kBackground.b, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  // OpenGL counts rows from the bottom.
  glViewport(viewport.x, window_height - viewport.y - viewport.height, viewport.width,
             viewport.height);
  glEnable(GL_DEPTH_TEST);
  glDisable(GL_CULL_FACE);
  glUseProgram(program_);
  const Eigen::Matrix4f m = view_projection.cast<float>();  // column-major, as GL reads it
  glUniformMatrix4fv(view_projection_, 1, GL_FALSE, m.data());
  // Toward the light: above, in front of the beam and toward its far end.
  const Eigen::Vector3f light = Eigen::Vector3f(0.35f, 1.0f, 0.6f).normalized();
  glUniform3f(light_, light.x(), light.y(), light.z());
  glBindVertexArray(vertex_array_);
  glBindBuffer(GL_ARRAY_BUFFER, buffer_);
}

void Renderer::Draw(const Mesh& mesh, const Colour& colour) {
  if (mesh.VertexCount() == 0) return;
  glUniform3f(colour_, colour.r, colour.g, colour.b);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.vertices.size() * sizeof(float)),
               mesh.vertices.data(), GL_STREAM_DRAW);
  glDrawArrays(GL_TRIANGLES, 0, mesh.VertexCount());
}

void Renderer::EndScene(int window_width, int window_height) {
  glBindVertexArray(0);
  glUseProgram(0);
  glDisable(GL_DEPTH_TEST);
  glViewport(0, 0, window_width, window_height);
}

}  // namespace cosmems::viewer
