// anvil_render: quick-look pictures of a run's VTK series, headless (issue
// 29). Reads DIR/anvil.pvd, draws the bodies' surface coloured by a field
// with a labelled colour bar, the dies semi-transparent, the time, stroke and
// load in a caption, and writes DIR/render/<field>_<increment>.png. Debian's
// VTK renders through X only (docs/libraries.md §3): `anvil render`
// starts this program under xvfb-run when there is no display. Kept apart
// from the solver: only this program links VTK's rendering.
#include "anvil/core/subprocess.h"
#include "anvil/io/RunResults.h"
#include "render_frames.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellData.h>
#include <vtkContourFilter.h>
#include <vtkCutter.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkFieldData.h>
#include <vtkImageAppend.h>
#include <vtkImageData.h>
#include <vtkImageResize.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlane.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkReflectionFilter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace {

bool has_field(vtkUnstructuredGrid* grid, const std::string& name) {
  return grid->GetPointData()->HasArray(name.c_str()) || grid->GetCellData()->HasArray(name.c_str());
}

/// A written increment's grids: the bodies, then each die.
using Grids = std::vector<vtkSmartPointer<vtkUnstructuredGrid>>;

/// The grids of `grids` that carry `field`: the bodies, or else the dies
/// that have it (a die field: underfill).
std::vector<vtkUnstructuredGrid*> carriers(const Grids& grids, const std::string& field) {
  if (has_field(grids.front(), field)) return {grids.front()};
  std::vector<vtkUnstructuredGrid*> dies;
  for (std::size_t p = 1; p < grids.size(); ++p)
    if (has_field(grids[p], field)) dies.push_back(grids[p]);
  return dies;
}

/// The field to colour by: `asked` (on the bodies or on dies), else
/// temperature, ε̄, von Mises stress of the bodies, in that order.
std::string choose_field(const Grids& grids, const std::string& asked) {
  if (!asked.empty()) {
    if (carriers(grids, asked).empty()) throw std::runtime_error("field '" + asked + "' is not in the series");
    return asked;
  }
  for (const char* name : {"temperature", "equivalent_strain", "von_mises_stress"})
    if (has_field(grids.front(), name)) return name;
  throw std::runtime_error("the series has none of temperature, equivalent_strain, von_mises_stress");
}

/// The values of `field` on `grid`, on its points or its cells.
vtkDataArray* field_values(vtkUnstructuredGrid* grid, const std::string& field) {
  vtkDataArray* points = grid->GetPointData()->GetArray(field.c_str());
  return points ? points : grid->GetCellData()->GetArray(field.c_str());
}

/// [low, high] of `field` over the grids that carry it (the magnitude of a vector field).
std::array<double, 2> field_range(const Grids& grids, const std::string& field) {
  std::array<double, 2> range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};
  for (vtkUnstructuredGrid* grid : carriers(grids, field)) {
    vtkDataArray* values = field_values(grid, field);
    std::array<double, 2> r{};
    values->GetRange(r.data(), values->GetNumberOfComponents() > 1 ? -1 : 0);
    range = {std::min(range[0], r[0]), std::max(range[1], r[1])};
  }
  return range;
}

/// `range` widened to ±1 % of its value when the field is uniform to round-off
/// (a patch test's stress): a colour bar spread over 1e-12 MPa would paint
/// round-off as bands.
std::array<double, 2> readable(std::array<double, 2> range) {
  const double size = std::max(std::abs(range[0]), std::abs(range[1]));
  if (range[1] - range[0] > 1e-6 * size) return range;
  const double half = size > 0.0 ? 0.01 * size : 1.0;
  const double middle = 0.5 * (range[0] + range[1]);
  return {middle - half, middle + half};
}

constexpr int kFrameCentiseconds = 30; ///< how long an animation shows each frame

/// Runs `arguments` in `folder` (never through a shell), the program writing
/// `name`.part there, and renames that to `name` when it succeeds: an
/// animation is there whole or not at all.
bool run_into(const std::vector<std::string>& arguments, const std::filesystem::path& folder, const std::string& name) {
  const std::filesystem::path part = folder / (name + ".part"), file = folder / name;
  std::error_code ignored;
  anvil::subprocess::Options in_folder;
  in_folder.directory = folder.string();
  if (anvil::subprocess::run(arguments, in_folder) == 0 && std::filesystem::exists(part, ignored)) {
    std::filesystem::rename(part, file);
    std::printf("%s\n", file.c_str());
    return true;
  }
  std::filesystem::remove(part, ignored);
  return false;
}

/// The frames (file names in `folder`) as an animated GIF by ImageMagick
/// (Debian's imagemagick: tools/setup). False when it could not be made.
bool animate_gif(const std::vector<std::string>& frames, const std::filesystem::path& folder, const std::string& name) {
  std::vector<std::string> arguments = {"convert", "-delay", std::to_string(kFrameCentiseconds), "-loop", "0"};
  arguments.insert(arguments.end(), frames.begin(), frames.end());
  arguments.push_back("GIF:" + name + ".part");
  if (run_into(arguments, folder, name)) return true;
  std::fprintf(stderr, "anvil render: %s not written (ImageMagick's convert failed or is missing)\n",
               (folder / name).c_str());
  return false;
}

/// The frames as an H.264 MP4 by ffmpeg when it is installed (tools/setup
/// does not install it: the GIF is what every machine gets). False when it
/// could not be made.
bool animate_mp4(const std::vector<std::string>& frames, const std::filesystem::path& folder, const std::string& name) {
  const std::string list = name + ".frames";
  {
    // The concat demuxer reads the names relative to the list, in the same folder.
    std::ofstream out(folder / list);
    for (const std::string& f : frames)
      out << "file '" << f << "'\nduration " << 0.01 * kFrameCentiseconds << "\n";
    out << "file '" << frames.back() << "'\n"; // the concat demuxer holds the last frame only when named again
  }
  const bool made = run_into({"ffmpeg", "-nostdin", "-loglevel", "error", "-y", "-f", "concat", "-safe", "0", "-i",
                              list, "-vf", "fps=10,format=yuv420p", "-c:v", "libx264", "-f", "mp4", name + ".part"},
                             folder, name);
  if (!made) std::fprintf(stderr, "anvil render: %s not written (ffmpeg failed)\n", (folder / name).c_str());
  std::error_code ignored;
  std::filesystem::remove(folder / list, ignored);
  return made;
}

/// The value of --frames: a whole number from 1 to 10000.
/// A bound of --range: a finite number.
double range_end(const std::string& text) {
  double x = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), x);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(x))
    throw std::runtime_error("--range needs two numbers, not '" + text + "'");
  return x;
}

int frame_count(const std::string& text) {
  int n = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), n);
  if (error != std::errc() || end != text.data() + text.size() || n < 1 || n > 10000)
    throw std::runtime_error("--frames needs a whole number from 1 to 10000, not '" + text + "'");
  return n;
}

struct Options {
  std::string directory, field, view = "iso";
  int frames = 1;
  bool mirror = false;          ///< a quarter model (symmetry planes x = 0, y = 0) drawn whole
  bool sheet = false;           ///< also a contact sheet of the frames
  std::string out;              ///< the last frame only, to this file
  double range[2] = {0.0, 0.0}; ///< colour bar range shared by the frames; empty: each frame's own
  bool fixed_range = false;     ///< --range: the user's, beyond it the colours saturate
  bool flow_lines = false;      ///< --flow-lines: a cut through the part with its flow lines
  bool operations = false;      ///< --operations: a chain's folder, the last frame of each operation
  int width = 1000, height = 750;
};

/// The surface of `grid`, mirrored across x = 0 and y = 0 when `mirror`.
vtkSmartPointer<vtkPolyData> surface_of(vtkUnstructuredGrid* grid, bool mirror) {
  vtkSmartPointer<vtkDataSet> whole = grid;
  if (mirror)
    for (const int plane : {vtkReflectionFilter::USE_X, vtkReflectionFilter::USE_Y}) {
      vtkNew<vtkReflectionFilter> reflect;
      reflect->SetInputData(whole);
      reflect->SetPlane(plane);
      reflect->SetCenter(0.0);
      reflect->CopyInputOn();
      reflect->Update();
      whole = vtkDataSet::SafeDownCast(reflect->GetOutput());
    }
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputData(whole);
  surface->Update();
  return surface->GetOutput();
}

/// A mapper colouring `shown` (a surface or a section) by `field` over `range` with `colours`.
vtkSmartPointer<vtkPolyDataMapper> coloured(vtkPolyData* shown, const std::string& field,
                                            const std::array<double, 2>& range, vtkLookupTable* colours) {
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(shown);
  mapper->SetLookupTable(colours);
  mapper->SetScalarRange(range.data());
  if (shown->GetPointData()->HasArray(field.c_str()))
    mapper->SetScalarModeToUsePointFieldData();
  else
    mapper->SetScalarModeToUseCellFieldData();
  mapper->SelectColorArray(field.c_str());
  mapper->ScalarVisibilityOn();
  return mapper;
}

/// `data` mirrored across the plane x = 0 too, when `mirror`, as surfaces and lines.
vtkSmartPointer<vtkPolyData> mirrored_across_x(vtkPolyData* data, bool mirror) {
  if (!mirror) return data;
  vtkNew<vtkReflectionFilter> reflect;
  reflect->SetInputData(data);
  reflect->SetPlane(vtkReflectionFilter::USE_X);
  reflect->SetCenter(0.0);
  reflect->CopyInputOn();
  vtkNew<vtkDataSetSurfaceFilter> surface;
  surface->SetInputConnection(reflect->GetOutputPort());
  surface->Update();
  return surface->GetOutput();
}

/// The flow lines (docs/reading-a-run.md §4): the bodies cut by a plane
/// through the press axis, normal to y (to x for planes of material normal
/// to y): just inside a model cut at 0 by a symmetry plane, else through the
/// middle. The section is coloured by `field`; the planes of material (the
/// level sets of material_<axis> at the series' flow_line_levels) are black
/// lines on it, the dies' profiles grey. Returns the section's actor, which
/// the camera frames; `normal` is the cut's axis.
vtkSmartPointer<vtkActor> add_flow_lines(vtkRenderer* renderer, const Options& o, const Grids& grids,
                                         const std::string& field, const std::array<double, 2>& range,
                                         vtkLookupTable* colours, int& normal) {
  vtkUnstructuredGrid* bodies = grids.front();
  int axis = -1;
  for (int k = 0; k < 3 && axis < 0; ++k)
    if (bodies->GetPointData()->HasArray((std::string("material_") + char('x' + k)).c_str())) axis = k;
  vtkDataArray* levels = bodies->GetFieldData()->GetArray("flow_line_levels");
  if (axis < 0 || !levels || levels->GetNumberOfTuples() == 0)
    throw std::runtime_error("the series has no flow lines (the case asks for them with output.flow_lines)");
  const std::string started = std::string("material_") + char('x' + axis);
  normal = axis == 1 ? 0 : 1;
  double bounds[6];
  bodies->GetBounds(bounds);
  const double low = bounds[2 * normal], high = bounds[2 * normal + 1], extent = high - low;
  const double at = std::abs(low) <= 1e-6 * extent ? low + 1e-3 * extent : 0.5 * (low + high);
  vtkNew<vtkPlane> plane;
  double origin[3] = {0.0, 0.0, 0.0}, direction[3] = {0.0, 0.0, 0.0};
  origin[normal] = at;
  direction[normal] = 1.0;
  plane->SetOrigin(origin);
  plane->SetNormal(direction);
  const bool mirror = o.mirror && normal == 1; // the section of a quarter model, drawn across x = 0 too
  auto cut = [&](vtkUnstructuredGrid* grid) {
    vtkNew<vtkCutter> cutter;
    cutter->SetCutFunction(plane);
    cutter->SetInputData(grid);
    cutter->Update();
    return vtkSmartPointer<vtkPolyData>(cutter->GetOutput());
  };
  const vtkSmartPointer<vtkPolyData> section = cut(bodies);
  const vtkSmartPointer<vtkPolyDataMapper> section_mapper =
      coloured(mirrored_across_x(section, mirror), field, range, colours);
  section_mapper->SetResolveCoincidentTopologyToPolygonOffset(); // the lines in front of the section they lie on
  vtkNew<vtkActor> section_actor;
  section_actor->SetMapper(section_mapper);
  section_actor->GetProperty()->SetOpacity(0.6); // the lines read over it
  renderer->AddActor(section_actor);
  vtkNew<vtkContourFilter> lines;
  lines->SetInputData(section);
  lines->SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, started.c_str());
  for (vtkIdType k = 0; k < levels->GetNumberOfTuples(); ++k)
    lines->SetValue(static_cast<int>(k), levels->GetTuple1(k));
  lines->Update();
  auto draw_lines = [&](vtkPolyData* data, double shade, float width) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(mirrored_across_x(data, mirror));
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(shade, shade, shade);
    actor->GetProperty()->SetLineWidth(width);
    renderer->AddActor(actor);
  };
  draw_lines(lines->GetOutput(), 0.0, 2.0f);
  for (std::size_t p = 1; p < grids.size(); ++p)
    draw_lines(cut(grids[p]), 0.45, 3.0f);
  return vtkSmartPointer<vtkActor>(section_actor.GetPointer());
}

/// The picture of one written increment, its grids read into `grids`. A
/// body field colours the bodies, the dies grey and see-through over them; a
/// die field (underfill) colours the dies, the part grey and see-through.
/// With --flow-lines: a cut through the part (add_flow_lines), seen along
/// the cut's normal.
vtkSmartPointer<vtkImageData> render(const Options& o, const anvil::io::SeriesEntry& frame, const Grids& grids,
                                     const std::vector<anvil::io::LoadRow>& loads, const std::string& load_surface) {
  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(1.0, 1.0, 1.0);
  const std::string field = choose_field(grids, o.field);
  const bool on_dies = !has_field(grids.front(), field);
  std::array<double, 2> range{o.range[0], o.range[1]};
  if (!(range[1] > range[0])) range = field_range(grids, field);
  range = readable(range);
  vtkNew<vtkLookupTable> colours;
  colours->SetHueRange(0.667, 0.0); // blue (low) to red (high)
  colours->Build();
  auto grey = [&](vtkUnstructuredGrid* grid, double opacity) {
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(surface_of(grid, o.mirror));
    mapper->ScalarVisibilityOff();
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetColor(0.6, 0.6, 0.65);
    actor->GetProperty()->SetOpacity(opacity);
    renderer->AddActor(actor);
    return vtkSmartPointer<vtkActor>(actor.GetPointer());
  };
  vtkSmartPointer<vtkActor> part;
  std::string view = o.view;
  if (o.flow_lines) {
    if (on_dies) throw std::runtime_error("--flow-lines colours the part's section: '" + field + "' is a die field");
    int normal = 1;
    part = add_flow_lines(renderer, o, grids, field, range, colours, normal);
    view = normal == 1 ? "front" : "side";
  } else {
    if (on_dies)
      part = grey(grids.front(), 0.3);
    else {
      part = vtkSmartPointer<vtkActor>::New();
      part->SetMapper(coloured(surface_of(grids.front(), o.mirror), field, range, colours));
      renderer->AddActor(part);
    }
    for (std::size_t p = 1; p < grids.size(); ++p)
      if (on_dies && has_field(grids[p], field)) {
        vtkNew<vtkActor> die;
        die->SetMapper(coloured(surface_of(grids[p], o.mirror), field, range, colours));
        renderer->AddActor(die);
      } else
        grey(grids[p], 0.2);
  }
  vtkNew<vtkScalarBarActor> bar;
  bar->SetLookupTable(colours);
  bar->SetTitle(field.c_str());
  bar->SetNumberOfLabels(5);
  bar->GetTitleTextProperty()->SetColor(0.0, 0.0, 0.0);
  bar->GetLabelTextProperty()->SetColor(0.0, 0.0, 0.0);
  bar->SetWidth(0.1);
  bar->SetHeight(0.6);
  bar->SetPosition(0.88, 0.2);
  renderer->AddViewProp(bar);
  char caption[256];
  std::snprintf(caption, sizeof caption, "increment %d   t %.4g s", frame.increment, frame.time);
  // A chain's frame names its operation (its folder, docs/chains.md).
  const std::string operation = std::filesystem::path(frame.parts.front()).parent_path().string();
  std::string text = (operation.empty() ? "" : operation + "   ") + caption;
  for (const anvil::io::LoadRow& row : loads)
    if (row.increment == frame.increment) {
      std::snprintf(caption, sizeof caption, "   stroke %.4g mm   press load(%s) %.4g kN, whole part", row.stroke,
                    load_surface.c_str(), row.whole_part_load / 1e3);
      text += caption;
    }
  vtkNew<vtkTextActor> label;
  label->SetInput(text.c_str());
  label->GetTextProperty()->SetColor(0.0, 0.0, 0.0);
  label->GetTextProperty()->SetFontSize(20);
  label->SetPosition(15, 15);
  renderer->AddViewProp(label);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(0, 0, 0);
  if (view == "top") {
    camera->SetPosition(0, 0, 1);
    camera->SetViewUp(0, 1, 0);
  } else if (view == "front") {
    camera->SetPosition(0, -1, 0);
    camera->SetViewUp(0, 0, 1);
  } else if (view == "side") {
    camera->SetPosition(1, 0, 0);
    camera->SetViewUp(0, 0, 1);
  } else {
    camera->SetPosition(1, -1.4, 0.9);
    camera->SetViewUp(0, 0, 1);
  }
  renderer->ResetCamera(part->GetBounds());
  camera->Zoom(1.1);

  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->AddRenderer(renderer);
  window->SetSize(o.width, o.height);
  window->Render();
  vtkNew<vtkWindowToImageFilter> image;
  image->SetInput(window);
  image->Update();
  vtkSmartPointer<vtkImageData> picture = vtkSmartPointer<vtkImageData>::New();
  picture->DeepCopy(image->GetOutput());
  return picture;
}

/// Writes `picture` to `file` whole (through `file`.part) or throws naming it.
void write_png(vtkImageData* picture, const std::string& file) {
  const std::string part = file + ".part";
  vtkNew<vtkPNGWriter> writer;
  writer->SetFileName(part.c_str());
  writer->SetInputData(picture);
  writer->Write();
  std::error_code error;
  if (writer->GetErrorCode() == 0 && std::filesystem::exists(part, error)) std::filesystem::rename(part, file, error);
  if (writer->GetErrorCode() != 0 || error || !std::filesystem::exists(file)) {
    std::filesystem::remove(part, error);
    throw std::runtime_error("cannot write " + file);
  }
}

/// The frames at half size, two to a row, in order (a report's page).
vtkSmartPointer<vtkImageData> contact_sheet(const std::vector<vtkSmartPointer<vtkImageData>>& pictures) {
  vtkNew<vtkImageAppend> rows;
  rows->SetAppendAxis(1);
  // vtkImageAppend stacks rows bottom-up: the last row first.
  const std::size_t columns = 2, row_count = (pictures.size() + columns - 1) / columns;
  for (std::size_t r = row_count; r-- > 0;) {
    vtkNew<vtkImageAppend> row;
    row->SetAppendAxis(0);
    for (std::size_t c = 0; c < columns; ++c) {
      const std::size_t k = r * columns + c;
      vtkNew<vtkImageResize> half;
      half->SetInputData(k < pictures.size() ? pictures[k] : pictures.back());
      half->SetMagnificationFactors(0.5, 0.5, 1.0);
      half->SetResizeMethodToMagnificationFactors();
      half->Update();
      vtkSmartPointer<vtkImageData> tile = vtkSmartPointer<vtkImageData>::New();
      tile->DeepCopy(half->GetOutput());
      if (k >= pictures.size()) tile->GetPointData()->GetScalars()->Fill(255.0); // an empty place stays white
      row->AddInputData(tile);
    }
    row->Update();
    vtkSmartPointer<vtkImageData> strip = vtkSmartPointer<vtkImageData>::New();
    strip->DeepCopy(row->GetOutput());
    rows->AddInputData(strip);
  }
  rows->Update();
  vtkSmartPointer<vtkImageData> sheet = vtkSmartPointer<vtkImageData>::New();
  sheet->DeepCopy(rows->GetOutput());
  return sheet;
}

} // namespace

int main(int argc, char** argv) {
  vtkObject::GlobalWarningDisplayOff(); // failures are said once, by us, naming the file
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw std::runtime_error(arg + " needs a value");
      return argv[++i];
    };
    try {
      if (arg == "--field")
        o.field = value();
      else if (arg == "--view")
        o.view = value();
      else if (arg == "--frames")
        o.frames = frame_count(value());
      else if (arg == "--mirror")
        o.mirror = true;
      else if (arg == "--sheet")
        o.sheet = true;
      else if (arg == "--flow-lines")
        o.flow_lines = true;
      else if (arg == "--operations")
        o.operations = true;
      else if (arg == "--out")
        o.out = value();
      else if (arg == "--range") {
        o.range[0] = range_end(value());
        o.range[1] = range_end(value());
        if (!(o.range[1] > o.range[0])) throw std::runtime_error("--range needs LOW below HIGH");
        o.fixed_range = true;
      } else if (arg[0] == '-')
        throw std::runtime_error("unknown option '" + arg + "'");
      else
        o.directory = arg;
    } catch (const std::exception& e) {
      std::fprintf(stderr, "anvil render: %s\n", e.what());
      return 2;
    }
  }
  if (o.directory.empty() || !(o.view == "iso" || o.view == "front" || o.view == "top") || o.frames < 1) {
    std::fprintf(stderr,
                 "usage: anvil render DIR [--field NAME] [--range LOW HIGH] [--view iso|front|top] [--frames N] "
                 "[--mirror] [--sheet] [--flow-lines] [--operations]\n");
    return 2;
  }
  try {
    // The frames: a chain's operation ends, or evenly spread over the
    // series, the last one always included.
    const std::vector<anvil::render::Shot> shots =
        o.operations ? anvil::render::operation_ends(o.directory)
                     : anvil::render::spread_frames(o.directory, o.out.empty() ? o.frames : 1);
    auto grids_of = [&](const anvil::io::SeriesEntry& frame) {
      Grids grids;
      for (const std::string& file : frame.parts)
        grids.push_back(anvil::io::read_grid(o.directory + "/" + file));
      return grids;
    };
    if (!o.out.empty()) {
      const anvil::render::Shot& last = shots.back();
      write_png(render(o, last.frame, grids_of(last.frame), last.loads->rows, last.loads->surface), o.out);
      std::printf("%s\n", o.out.c_str());
      return 0;
    }
    const std::string picture_name = o.flow_lines ? "flow_lines" : o.field.empty() ? "default" : o.field;
    const std::filesystem::path folder = std::filesystem::path(o.directory) / "render";
    std::filesystem::create_directories(folder);
    const std::size_t count = shots.size();
    std::vector<Grids> grids;
    for (const anvil::render::Shot& s : shots)
      grids.push_back(grids_of(s.frame));
    if (count > 1 && !o.fixed_range) {
      // One colour bar for every frame, so the animation and the sheet compare.
      o.range[0] = std::numeric_limits<double>::infinity();
      o.range[1] = -o.range[0];
      for (const Grids& g : grids) {
        const std::array<double, 2> r = field_range(g, choose_field(g, o.field));
        o.range[0] = std::min(o.range[0], r[0]);
        o.range[1] = std::max(o.range[1], r[1]);
      }
    }
    std::vector<vtkSmartPointer<vtkImageData>> pictures;
    std::vector<std::string> files; // in `folder`
    for (std::size_t k = 0; k < count; ++k) {
      char name[160];
      const anvil::io::SeriesEntry& frame = shots[k].frame;
      const std::string operation = std::filesystem::path(frame.parts.front()).parent_path().string();
      std::snprintf(name, sizeof name, "%s%s%s_%06d.png", operation.c_str(), operation.empty() ? "" : "_",
                    picture_name.c_str(), frame.increment);
      pictures.push_back(render(o, frame, grids[k], shots[k].loads->rows, shots[k].loads->surface));
      files.push_back(name);
      write_png(pictures.back(), (folder / name).string());
      std::printf("%s\n", (folder / name).c_str());
    }
    const std::string stem = (folder / picture_name).string();
    if (o.sheet && pictures.size() > 1) {
      write_png(contact_sheet(pictures), stem + "_sheet.png");
      std::printf("%s\n", (stem + "_sheet.png").c_str());
    }
    if (pictures.size() > 1) {
      const std::string& animation = picture_name;
      bool made = animate_gif(files, folder, animation + ".gif");
      if (anvil::subprocess::on_path("ffmpeg")) made = animate_mp4(files, folder, animation + ".mp4") && made;
      if (!made) return 1;
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "anvil render: %s\n", e.what());
    return 1;
  }
  return 0;
}
