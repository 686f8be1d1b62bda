// The only translation unit of the renderer that includes VTK.
#include "viz/motion_renderer.h"

#include <fmt/format.h>
#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkLightKit.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <vector>

#include "kernel/assembly/assembly_state.h"
#include "kernel/geometry/aabb.h"
#include "viz/display.h"
#include "viz/display_colors.h"
#include "viz/feature_lines.h"

namespace mechanist {
namespace {

vtkSmartPointer<vtkPolyData> Triangles(const TriangleMesh& mesh) {
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(static_cast<vtkIdType>(mesh.vertices.size()));
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    points->SetPoint(static_cast<vtkIdType>(i), mesh.vertices[i].data());
  }
  vtkNew<vtkCellArray> cells;
  for (const TriangleMesh::Face& f : mesh.faces) {
    const vtkIdType ids[3] = {f[0], f[1], f[2]};
    cells->InsertNextCell(3, ids);
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetPolys(cells);
  return data;
}

// The lines of a part's features (FeatureLines) as VTK polylines, in the part's frame.
vtkSmartPointer<vtkPolyData> FeatureAxes(const Part& part, bool pitch_circles) {
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> lines;
  for (const std::vector<Eigen::Vector3d>& line : FeatureLines(part, pitch_circles)) {
    std::vector<vtkIdType> ids;
    for (const Eigen::Vector3d& p : line) ids.push_back(points->InsertNextPoint(p.data()));
    lines->InsertNextCell(static_cast<vtkIdType>(ids.size()), ids.data());
  }
  auto data = vtkSmartPointer<vtkPolyData>::New();
  data->SetPoints(points);
  data->SetLines(lines);
  return data;
}

void SetPose(vtkActor* actor, const RigidTransform& X_WP) {
  vtkNew<vtkMatrix4x4> m;
  const Eigen::Matrix4d x = X_WP.matrix();
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) m->SetElement(i, j, x(i, j));
  }
  actor->SetUserMatrix(m);
}

}  // namespace

std::optional<View> ParseView(std::string_view name) {
  if (name == "iso") return View::kIso;
  if (name == "front") return View::kFront;
  if (name == "top") return View::kTop;
  if (name == "side") return View::kSide;
  return std::nullopt;
}

struct MotionRenderer::Impl {
  const Animation* animation = nullptr;
  std::string title;
  std::vector<Eigen::Vector3d> colors;
  std::vector<vtkSmartPointer<vtkActor>> parts;  // per part, null without a mesh
  std::vector<vtkSmartPointer<vtkActor>> axes;   // per part, null without axes
  vtkNew<vtkRenderer> renderer;
  vtkNew<vtkRenderWindow> window;
  vtkNew<vtkTextActor> text;
  vtkNew<vtkWindowToImageFilter> grab;
};

MotionRenderer::MotionRenderer(const Assembly& assembly, const Analysis& analysis,
                               const Animation& animation, const RenderOptions& options,
                               const TriangleMesh* gap_surface_W)
    : impl_(std::make_unique<Impl>()) {
  if (options.width < 16 || options.height < 16 || options.width > 8192 || options.height > 8192) {
    throw std::invalid_argument("MotionRenderer: the image size must be 16 to 8192 pixels");
  }
  std::string reason;
  if (!DisplayAvailable(&reason)) throw std::runtime_error(reason);
  Impl& r = *impl_;
  r.animation = &animation;
  r.title = options.title.empty() ? assembly.name() : options.title;
  r.colors = ColorParts(analysis).part;
  const bool gaps = gap_surface_W != nullptr && !gap_surface_W->faces.empty();

  const std::size_t n = assembly.parts().size();
  r.parts.resize(n);
  r.axes.resize(n);
  std::map<const TriangleMesh*, vtkSmartPointer<vtkPolyData>> shared;
  for (std::size_t p = 0; p < n; ++p) {
    const Part& part = assembly.part(p);
    if (part.mesh && !part.mesh->faces.empty()) {
      auto& data = shared[part.mesh.get()];
      if (!data) data = Triangles(*part.mesh);
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(data);
      r.parts[p] = vtkSmartPointer<vtkActor>::New();
      r.parts[p]->SetMapper(mapper);
      r.parts[p]->GetProperty()->SetInterpolationToFlat();
      if (gaps) r.parts[p]->GetProperty()->SetOpacity(0.25);
      r.renderer->AddActor(r.parts[p]);
    }
    // A features-only part is drawn by its axes alone, in its own colour and always.
    const bool sketch = !part.HasGeometry();
    if ((options.feature_axes || sketch) && !part.features.empty()) {
      vtkNew<vtkPolyDataMapper> mapper;
      mapper->SetInputData(FeatureAxes(part, sketch));
      r.axes[p] = vtkSmartPointer<vtkActor>::New();
      r.axes[p]->SetMapper(mapper);
      const Eigen::Vector3d c = sketch ? r.colors[p] : AxisColor();
      r.axes[p]->GetProperty()->SetColor(c.x(), c.y(), c.z());
      r.axes[p]->GetProperty()->SetLineWidth(sketch ? 4.0 : 1.0);
      r.axes[p]->GetProperty()->LightingOff();
      r.renderer->AddActor(r.axes[p]);
    }
  }
  Aabb bounds;
  for (const AssemblyState& state : animation.states) {
    for (std::size_t p = 0; p < n; ++p) {
      if (r.parts[p]) bounds.Extend(WorldBox(assembly, state, p));
      if (r.axes[p] && !r.parts[p]) {
        const double* b = r.axes[p]->GetMapper()->GetInput()->GetBounds();
        bounds.Extend(TransformBox(state.X_WP[p], Aabb{{b[0], b[2], b[4]}, {b[1], b[3], b[5]}}));
      }
    }
  }
  if (gaps) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(Triangles(*gap_surface_W));
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    const Eigen::Vector3d c = GapColor();
    actor->GetProperty()->SetColor(c.x(), c.y(), c.z());
    r.renderer->AddActor(actor);
    bounds.Extend(gap_surface_W->Bounds());
    r.renderer->SetUseDepthPeeling(1);
  }
  if (bounds.empty()) bounds = Aabb{Eigen::Vector3d::Constant(-1), Eigen::Vector3d::Constant(1)};

  // Key, fill and back lights shade the faces of a part apart, so that parts of one colour
  // (the ground's) stay distinguishable.
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(r.renderer);
  r.renderer->SetBackground(1.0, 1.0, 1.0);
  r.renderer->SetBackground2(0.82, 0.85, 0.90);
  r.renderer->GradientBackgroundOn();
  r.renderer->UseFXAAOn();
  r.text->GetTextProperty()->SetFontSize(std::max(10, options.height / 32));
  r.text->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
  r.text->GetTextProperty()->SetJustificationToLeft();
  r.text->GetTextProperty()->SetVerticalJustificationToTop();
  r.text->SetDisplayPosition(10, options.height - 10);
  r.renderer->AddActor2D(r.text);

  // The camera looks at the centre of everything the run covers, from far enough for its
  // bounding sphere to fit the narrower field of view.
  const Eigen::Vector3d center = bounds.center();
  const double radius = std::max(0.5 * bounds.size().norm(), 1e-3);
  Eigen::Vector3d from(1.0, -1.0, 1.0), up(0.0, 0.0, 1.0);
  if (options.view == View::kFront) from = {0.0, -1.0, 0.0};
  if (options.view == View::kSide) from = {1.0, 0.0, 0.0};
  if (options.view == View::kTop) from = {0.0, 0.0, 1.0}, up = {0.0, 1.0, 0.0};
  vtkCamera* camera = r.renderer->GetActiveCamera();
  const double angle = 30.0;  // vertical field of view, degrees
  camera->SetViewAngle(angle);
  const double narrow = std::min(1.0, static_cast<double>(options.width) / options.height) *
                        std::tan(0.5 * angle * M_PI / 180.0);
  const Eigen::Vector3d eye =
      center + from.normalized() * (1.05 * radius / std::sin(std::atan(narrow)));
  camera->SetFocalPoint(center.data());
  camera->SetPosition(eye.data());
  camera->SetViewUp(up.data());
  double box[6] = {bounds.min.x(), bounds.max.x(), bounds.min.y(),
                   bounds.max.y(), bounds.min.z(), bounds.max.z()};
  r.renderer->ResetCameraClippingRange(box);

  r.window->SetOffScreenRendering(1);
  r.window->SetMultiSamples(0);
  r.window->SetSize(options.width, options.height);
  r.window->AddRenderer(r.renderer);
  r.grab->SetInput(r.window);
  r.grab->SetInputBufferTypeToRGB();
  r.grab->ReadFrontBufferOff();
}

MotionRenderer::~MotionRenderer() = default;

Image MotionRenderer::Render(std::size_t frame) {
  Impl& r = *impl_;
  if (frame >= r.animation->frame_count()) {
    throw std::out_of_range(fmt::format("MotionRenderer::Render: no frame {}", frame));
  }
  const AssemblyState& state = r.animation->states[frame];
  for (std::size_t p = 0; p < r.parts.size(); ++p) {
    if (r.parts[p]) {
      SetPose(r.parts[p], state.X_WP[p]);
      const Eigen::Vector3d c = r.animation->InClash(p, frame) ? ClashColor() : r.colors[p];
      r.parts[p]->GetProperty()->SetColor(c.x(), c.y(), c.z());
    }
    if (r.axes[p]) SetPose(r.axes[p], state.X_WP[p]);
  }
  const std::string title = r.title.empty()
                                ? r.animation->labels[frame]
                                : fmt::format("{} | {}", r.title, r.animation->labels[frame]);
  r.text->SetInput(title.c_str());
  r.window->Render();
  r.grab->Modified();
  r.grab->Update();
  vtkImageData* data = r.grab->GetOutput();
  int dims[3];
  data->GetDimensions(dims);
  Image image;
  image.width = dims[0];
  image.height = dims[1];
  image.rgb.resize(static_cast<std::size_t>(dims[0]) * dims[1] * 3);
  const auto* pixels = static_cast<const std::uint8_t*>(data->GetScalarPointer());
  const std::size_t row = static_cast<std::size_t>(dims[0]) * 3;
  for (int y = 0; y < dims[1]; ++y) {  // VTK's rows go up from the bottom
    std::memcpy(image.rgb.data() + row * y, pixels + row * (dims[1] - 1 - y), row);
  }
  return image;
}

Eigen::Vector2d MotionRenderer::PixelOf(const Eigen::Vector3d& p_W) const {
  vtkRenderer* renderer = impl_->renderer;
  renderer->SetWorldPoint(p_W.x(), p_W.y(), p_W.z(), 1.0);
  renderer->WorldToDisplay();
  const double* d = renderer->GetDisplayPoint();
  return {d[0], impl_->window->GetSize()[1] - 1 - d[1]};
}

}  // namespace mechanist
