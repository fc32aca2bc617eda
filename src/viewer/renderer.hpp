#pragma once

#include <Eigen/Core>

#include "gl.hpp"
#include "mesh.hpp"
#include "palette.hpp"
#include "viewport.hpp"

namespace cosmems::viewer {

/// Draws meshes in one flat colour each, lit by a fixed light from above and in front plus an
/// ambient part: the shading scales the colour, it never changes its hue. Needs a current
/// OpenGL 3.3 core context for its whole life.
class Renderer {
 public:
  /// Compiles the shaders; throws std::runtime_error with the driver's log when they fail.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Clears the window to the background, then sets up `viewport` (of a window
  /// `window_height` pixels high) with depth testing for Draw().
  void BeginScene(int window_width, int window_height, const Viewport& viewport,
                  const Eigen::Matrix4d& view_projection);
  /// Draws `mesh` (uploaded anew: the meshes are a few thousand vertices).
  void Draw(const Mesh& mesh, const Colour& colour);
  /// Restores the state the panel's drawing expects (whole window, no depth test).
  void EndScene(int window_width, int window_height);

 private:
  GLuint program_ = 0;
  GLuint vertex_array_ = 0;
  GLuint buffer_ = 0;
  GLint view_projection_ = -1;
  GLint colour_ = -1;
  GLint light_ = -1;
};

}  // namespace cosmems::viewer
