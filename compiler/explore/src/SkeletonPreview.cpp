#include "voxc/explore/SkeletonPreview.h"

#include "Canvas.h"
#include "voxc/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <glm/common.hpp>

namespace voxc::explore {

namespace {

constexpr Rgb kBackground{250, 250, 247};
constexpr Rgb kFrame{170, 170, 165};
constexpr Rgb kCaptionInk{40, 40, 40};
constexpr Rgb kConnection{214, 39, 40};
constexpr Rgb kEndpoint{31, 119, 180};
constexpr int kMargin = 8;
constexpr int kCaptionScale = 2;

Rgb segmentColor(lsystem::SymbolType type) {
    switch (type) {
    case lsystem::SymbolType::Tunnel: return {90, 90, 90};
    case lsystem::SymbolType::Room: return {230, 110, 10};
    case lsystem::SymbolType::None: break;
    }
    return {44, 150, 44};
}

// Maps skeleton coordinates (two axes) into a view's square: one scale for both views.
struct Projection {
    glm::dvec3 min{0.0}, max{0.0};
    double scale = 1.0;
    int left = 0, top = 0, size = 1;
    int axisU = 0, axisV = 2; // horizontal and vertical skeleton axes of this view
    bool vUp = false;         // the side view puts +y at the top

    std::pair<int, int> operator()(glm::dvec3 p) const {
        const double span = std::max(max[axisU] - min[axisU], max[axisV] - min[axisV]);
        const double u = (p[axisU] - min[axisU]) * scale, v = (p[axisV] - min[axisV]) * scale;
        const double pad = (size - span * scale) / 2.0;
        const int x = left + int(std::lround(pad + u));
        const int y = vUp ? top + size - 1 - int(std::lround(pad + v)) : top + int(std::lround(pad + v));
        return {x, y};
    }
};

void drawView(Image& image, const lsystem::Skeleton& skeleton, const Projection& view) {
    fillRect(image, view.left - 1, view.top - 1, view.left + view.size, view.top - 1, kFrame);
    fillRect(image, view.left - 1, view.top + view.size, view.left + view.size, view.top + view.size, kFrame);
    fillRect(image, view.left - 1, view.top - 1, view.left - 1, view.top + view.size, kFrame);
    fillRect(image, view.left + view.size, view.top - 1, view.left + view.size, view.top + view.size, kFrame);
    for (const lsystem::Connection& connection : skeleton.connections)
        for (size_t i = 1; i < connection.points.size(); ++i) {
            const auto [x0, y0] = view(connection.points[i - 1]);
            const auto [x1, y1] = view(connection.points[i]);
            drawLine(image, x0, y0, x1, y1, kConnection, 1);
        }
    for (const lsystem::Segment& segment : skeleton.segments) {
        const auto [x0, y0] = view(segment.from);
        const auto [x1, y1] = view(segment.to);
        drawLine(image, x0, y0, x1, y1, segmentColor(segment.type), 2);
    }
    for (const lsystem::Endpoint& endpoint : skeleton.endpoints) {
        const auto [x, y] = view(endpoint.position);
        fillRect(image, x - 2, y - 2, x + 2, y + 2, kEndpoint);
    }
}

} // namespace

Image renderSkeletonPreview(const lsystem::Skeleton& skeleton, const std::string& caption, int viewSize) {
    VOXC_ASSERT(viewSize >= 16);
    glm::dvec3 min(0.0), max(0.0);
    bool any = false;
    const auto include = [&](glm::dvec3 p) {
        min = any ? glm::min(min, p) : p;
        max = any ? glm::max(max, p) : p;
        any = true;
    };
    for (const lsystem::Segment& segment : skeleton.segments) {
        include(segment.from);
        include(segment.to);
    }
    for (const lsystem::Connection& connection : skeleton.connections)
        for (glm::dvec3 p : connection.points) include(p);
    const double span = std::max({max.x - min.x, max.y - min.y, max.z - min.z, 1e-9});
    const int inner = viewSize - 2 * kMargin;
    const double scale = double(inner) / span;

    const int captionHeight = textHeight(kCaptionScale) + 2 * kMargin;
    Image image(2 * viewSize + kMargin, viewSize + captionHeight, kBackground);
    const Projection top{min, max, scale, kMargin, kMargin, inner, 0, 2, false};
    const Projection side{min, max, scale, viewSize + kMargin, kMargin, inner, 0, 1, true};
    drawView(image, skeleton, top);
    drawView(image, skeleton, side);
    drawText(image, top.left + 3, top.top + 3, "TOP X-Z", kFrame, 1);
    drawText(image, side.left + 3, side.top + 3, "SIDE X-Y", kFrame, 1);
    drawText(image, kMargin, viewSize + kMargin, caption, kCaptionInk, kCaptionScale);
    return image;
}

Image contactSheet(const std::vector<Image>& previews, const std::vector<std::string>& labels, int columns) {
    VOXC_ASSERT(!previews.empty() && previews.size() == labels.size() && columns >= 1);
    int cellWidth = 0, cellHeight = 0;
    for (const Image& preview : previews) {
        cellWidth = std::max(cellWidth, preview.width);
        cellHeight = std::max(cellHeight, preview.height);
    }
    const int labelHeight = textHeight(kCaptionScale) + kMargin;
    cellHeight += labelHeight;
    const int rows = int((previews.size() + size_t(columns) - 1) / size_t(columns));
    const int shown = std::min(columns, int(previews.size()));
    Image sheet(shown * (cellWidth + kMargin) + kMargin, rows * (cellHeight + kMargin) + kMargin, {255, 255, 255});
    for (size_t i = 0; i < previews.size(); ++i) {
        const int left = kMargin + int(i % size_t(columns)) * (cellWidth + kMargin);
        const int top = kMargin + int(i / size_t(columns)) * (cellHeight + kMargin);
        drawText(sheet, left, top, labels[i], kCaptionInk, kCaptionScale);
        const Image& preview = previews[i];
        for (int y = 0; y < preview.height; ++y)
            for (int x = 0; x < preview.width; ++x) sheet.set(left + x, top + labelHeight + y, preview.at(x, y));
    }
    return sheet;
}

} // namespace voxc::explore
