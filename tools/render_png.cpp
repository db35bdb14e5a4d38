// nvv_render: renders one or more coloured meshes side by side into a PNG, headless.
// A small z-buffered rasteriser (orthographic view, per-vertex colours, Lambert shading),
// so the project's pictures need no OpenGL and no display.
//
// Usage: nvv_render OUT.png WIDTH HEIGHT YAW_DEG PITCH_DEG MESH.ply [LABEL] [MESH.ply [LABEL]] ...
#include <QGuiApplication>
#include <QImage>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include <vcg/complex/complex.h>
#include <vcg/complex/algorithms/update/bounding.h>
#include <vcg/complex/algorithms/update/normal.h>
#include <wrap/io_trimesh/import.h>

namespace {
class RVertex;
class RFace;
struct RTypes : vcg::UsedTypes<vcg::Use<RVertex>::AsVertexType, vcg::Use<RFace>::AsFaceType> {};
class RVertex : public vcg::Vertex<RTypes, vcg::vertex::Coord3f, vcg::vertex::Normal3f, vcg::vertex::Color4b,
                                   vcg::vertex::BitFlags> {};
class RFace : public vcg::Face<RTypes, vcg::face::VertexRef, vcg::face::Normal3f, vcg::face::BitFlags> {};
class RMesh : public vcg::tri::TriMesh<std::vector<RVertex>, std::vector<RFace>> {};

// Renders m into the (x0, 0, w, h) panel of img.
void RenderPanel(const RMesh& m, QImage& img, int x0, int w, int h, double yaw, double pitch) {
  const double cy = std::cos(yaw), sy = std::sin(yaw), cp = std::cos(pitch), sp = std::sin(pitch);
  auto view = [&](const vcg::Point3f& p) {  // rotate about z (yaw), then tilt about x (pitch)
    const double x = cy * p[0] - sy * p[1], y = sy * p[0] + cy * p[1], z = p[2];
    return vcg::Point3d(x, cp * y - sp * z, sp * y + cp * z);  // (screen x, depth, screen y)
  };
  vcg::Box3d box;
  for (const auto& v : m.vert) box.Add(view(v.cP()));
  const double scale = 0.9 * std::min(w / std::max(1e-12, box.DimX()), h / std::max(1e-12, box.DimZ()));
  const vcg::Point3d c = box.Center();
  std::vector<double> zbuf(std::size_t(w) * h, -std::numeric_limits<double>::infinity());
  const vcg::Point3d light = vcg::Point3d(0.3, -1.0, 0.5).Normalize();
  for (const auto& f : m.face) {
    if (f.IsD()) continue;
    double X[3], Y[3], Z[3], shade[3];
    for (int j = 0; j < 3; ++j) {
      const vcg::Point3d q = view(f.cV(j)->cP());
      X[j] = w / 2.0 + scale * (q[0] - c[0]);
      Y[j] = h / 2.0 - scale * (q[2] - c[2]);
      Z[j] = -(q[1] - c[1]);  // towards the viewer (looking along +depth)
      const vcg::Point3d n = view(f.cV(j)->cN());
      shade[j] = 0.35 + 0.65 * std::abs(n.dot(light) / std::max(1e-12, n.Norm()));
    }
    const double area = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (std::abs(area) < 1e-12) continue;
    const int xmin = std::max(0, int(std::floor(std::min({X[0], X[1], X[2]}))));
    const int xmax = std::min(w - 1, int(std::ceil(std::max({X[0], X[1], X[2]}))));
    const int ymin = std::max(0, int(std::floor(std::min({Y[0], Y[1], Y[2]}))));
    const int ymax = std::min(h - 1, int(std::ceil(std::max({Y[0], Y[1], Y[2]}))));
    for (int py = ymin; py <= ymax; ++py)
      for (int px = xmin; px <= xmax; ++px) {
        const double sx = px + 0.5, syy = py + 0.5;
        const double b0 = ((X[1] - sx) * (Y[2] - syy) - (X[2] - sx) * (Y[1] - syy)) / area;
        const double b1 = ((X[2] - sx) * (Y[0] - syy) - (X[0] - sx) * (Y[2] - syy)) / area;
        const double b2 = 1 - b0 - b1;
        if (b0 < 0 || b1 < 0 || b2 < 0) continue;
        const double z = b0 * Z[0] + b1 * Z[1] + b2 * Z[2];
        double& zb = zbuf[std::size_t(py) * w + px];
        if (z <= zb) continue;
        zb = z;
        double rgb[3] = {0, 0, 0};
        const double b[3] = {b0, b1, b2};
        for (int j = 0; j < 3; ++j)
          for (int k = 0; k < 3; ++k) rgb[k] += b[j] * shade[j] * f.cV(j)->cC()[k];
        img.setPixel(x0 + px, py, qRgb(int(std::min(255.0, rgb[0])), int(std::min(255.0, rgb[1])), int(std::min(255.0, rgb[2]))));
      }
  }
}
}  // namespace

int main(int argc, char** argv) {
  if (argc < 7) {
    std::fprintf(stderr, "usage: nvv_render OUT.png WIDTH HEIGHT YAW_DEG PITCH_DEG MESH.ply [LABEL] ...\n");
    return 2;
  }
  QGuiApplication app(argc, argv);  // fonts for the labels (QT_QPA_PLATFORM=offscreen is enough)
  const int w = std::atoi(argv[2]), h = std::atoi(argv[3]);
  const double yaw = std::atof(argv[4]) * M_PI / 180, pitch = std::atof(argv[5]) * M_PI / 180;
  std::vector<std::pair<std::string, std::string>> panels;
  for (int i = 6; i < argc; ++i) {
    std::string label;
    if (i + 1 < argc && std::string(argv[i + 1]).find(".ply") == std::string::npos) label = argv[i + 1];
    panels.push_back({argv[i], label});
    if (!label.empty()) ++i;
  }
  QImage img(w * int(panels.size()), h, QImage::Format_RGB32);
  img.fill(qRgb(255, 255, 255));
  for (std::size_t p = 0; p < panels.size(); ++p) {
    RMesh m;
    int mask = 0;
    if (vcg::tri::io::Importer<RMesh>::Open(m, panels[p].first.c_str(), mask) != 0) {
      std::fprintf(stderr, "nvv_render: cannot read %s\n", panels[p].first.c_str());
      return 3;
    }
    if (!(mask & vcg::tri::io::Mask::IOM_VERTNORMAL)) {
      vcg::tri::UpdateNormal<RMesh>::PerVertexAngleWeighted(m);
      vcg::tri::UpdateNormal<RMesh>::NormalizePerVertex(m);
    }
    if (!(mask & vcg::tri::io::Mask::IOM_VERTCOLOR))
      for (auto& v : m.vert) v.C() = vcg::Color4b(200, 200, 200, 255);
    RenderPanel(m, img, int(p) * w, w, h, yaw, pitch);
    if (!panels[p].second.empty()) {
      QPainter painter(&img);
      painter.setPen(Qt::black);
      QFont font = painter.font();
      font.setPixelSize(std::max(12, h / 28));
      painter.setFont(font);
      painter.drawText(QRect(int(p) * w, 4, w, h / 12), Qt::AlignHCenter | Qt::AlignTop, QString::fromStdString(panels[p].second));
    }
  }
  if (!img.save(QString::fromUtf8(argv[1]), "PNG")) {
    std::fprintf(stderr, "nvv_render: cannot write %s\n", argv[1]);
    return 5;
  }
  return 0;
}
