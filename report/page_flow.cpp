#include "report/page_flow.h"

#include <QFontMetricsF>
#include <QPaintDevice>
#include <QPainter>
#include <QTextLayout>

#include <algorithm>

namespace lucerna {

namespace {

// The margins (mm): left for binding, the header's and footer's bands.
constexpr double kLeftMm = 20, kRightMm = 15, kHeaderMm = 11, kTopMm = 22, kBottomMm = 20, kFooterMm = 12;
constexpr double kCellPadMm = 1.1;

QFont font(double points, bool bold = false) {
    QFont f(QStringLiteral("DejaVu Sans"));
    // No ligatures ("fi", "ffi"): text copied out of the PDF (a command line, a file name) reads
    // as typed. Latin text needs no other shaping.
    f.setStyleHint(QFont::SansSerif, QFont::PreferNoShaping);
    f.setPointSizeF(points);
    f.setBold(bold);
    return f;
}

}  // namespace

PageFlow::PageFlow(QPaintDevice& device) : device_(device) {
    fonts_.title = font(24, true);
    fonts_.subtitle = font(14);
    fonts_.heading = font(13, true);
    fonts_.subheading = font(10.5, true);
    fonts_.body = font(9.5);
    fonts_.bodyBold = font(9.5, true);
    fonts_.small = font(8);
    fonts_.table = font(8.5);
    fonts_.tableBold = font(8.5, true);
    fonts_.figure = font(7.5);
    fonts_.figureBold = font(7.5, true);
    dpmm_ = device.logicalDpiX() / 25.4;
    pageWidth_ = device.width();
    pageHeight_ = device.height();
    left_ = mm(kLeftMm);
    right_ = pageWidth_ - mm(kRightMm);
    top_ = mm(kTopMm);
    bottom_ = pageHeight_ - mm(kBottomMm);
    newPage();
}

double PageFlow::mm(double millimetres) const { return millimetres * dpmm_; }

void PageFlow::newPage() {
    pages_.emplace_back();
    y_ = top_;
}

void PageFlow::ensure(double height) {
    if (y_ + height > bottom_ && y_ > top_) newPage();
}

void PageFlow::space(double height) {
    if (y_ > top_) y_ = std::min(y_ + height, bottom_);
}

void PageFlow::add(Op op) { pages_.back().push_back(std::move(op)); }

double PageFlow::lineHeight(const QFont& f) const { return QFontMetricsF(f, &device_).lineSpacing(); }
double PageFlow::ascent(const QFont& f) const { return QFontMetricsF(f, &device_).ascent(); }

std::vector<QString> PageFlow::wrap(const QString& text, const QFont& f, double width) const {
    std::vector<QString> lines;
    for (const QString& paragraph : text.split('\n')) {
        if (paragraph.isEmpty()) {
            lines.emplace_back();
            continue;
        }
        QTextLayout layout(paragraph, f, &device_);
        QTextOption option;
        option.setWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
        layout.setTextOption(option);
        layout.beginLayout();
        for (QTextLine line = layout.createLine(); line.isValid(); line = layout.createLine()) {
            line.setLineWidth(width);
            lines.push_back(paragraph.mid(line.textStart(), line.textLength()).trimmed());
        }
        layout.endLayout();
    }
    return lines;
}

void PageFlow::textLine(const QString& text, const QFont& f, double x, double baseline, Qt::Alignment alignment,
                        double width) {
    double at = x;
    if (alignment & (Qt::AlignRight | Qt::AlignHCenter)) {
        const double advance = QFontMetricsF(f, &device_).horizontalAdvance(text);
        at = alignment & Qt::AlignRight ? x + width - advance : x + (width - advance) / 2;
    }
    add([text, f, at, baseline](QPainter& p) {
        p.setFont(f);
        p.setPen(Qt::black);
        p.drawText(QPointF(at, baseline), text);
    });
}

void PageFlow::title(const QString& text, const QFont& f) {
    const double h = lineHeight(f);
    for (const QString& line : wrap(text, f, width())) {
        ensure(h);
        textLine(line, f, left_, y_ + ascent(f));
        y_ += h;
    }
}

void PageFlow::heading(const QString& text) {
    // A heading never ends a page: keep room for a few lines after it.
    ensure(lineHeight(fonts_.heading) * 1.6 + 4 * lineHeight(fonts_.body));
    space(mm(3));
    title(text, fonts_.heading);
    const double y = y_ + mm(0.6), l = left_, r = right_, pen = mm(0.25);
    add([y, l, r, pen](QPainter& p) {
        p.setPen(QPen(QColor(120, 120, 120), pen));
        p.drawLine(QPointF(l, y), QPointF(r, y));
    });
    y_ += mm(2.5);
}

void PageFlow::subheading(const QString& text) {
    ensure(lineHeight(fonts_.subheading) * 1.4 + 3 * lineHeight(fonts_.body));
    space(mm(2));
    title(text, fonts_.subheading);
    y_ += mm(1);
}

void PageFlow::paragraph(const QString& text, const QFont& f, double indent) {
    const double h = lineHeight(f);
    for (const QString& line : wrap(text, f, width() - indent)) {
        ensure(h);
        textLine(line, f, left_ + indent, y_ + ascent(f));
        y_ += h;
    }
    y_ += mm(1.2);
}

void PageFlow::keyValues(const std::vector<std::pair<QString, QString>>& pairs, double keyShare) {
    const QFont& f = fonts_.body;
    const double h = lineHeight(f), keyWidth = width() * keyShare, gap = mm(3);
    for (const auto& [key, value] : pairs) {
        const std::vector<QString> keyLines = wrap(key, fonts_.bodyBold, keyWidth - gap);
        const std::vector<QString> valueLines = wrap(value, f, width() - keyWidth);
        const size_t n = std::max(keyLines.size(), valueLines.size());
        ensure(h * double(std::min<size_t>(n, 3)));
        for (size_t i = 0; i < n; ++i) {
            ensure(h);
            if (i < keyLines.size()) textLine(keyLines[i], fonts_.bodyBold, left_, y_ + ascent(f));
            if (i < valueLines.size()) textLine(valueLines[i], f, left_ + keyWidth, y_ + ascent(f));
            y_ += h;
        }
        y_ += mm(0.6);
    }
    y_ += mm(1);
}

ReportTable tableOf(const std::vector<ReportColumn>& columns) {
    ReportTable t;
    for (const ReportColumn& c : columns) {
        t.header.push_back(c.header);
        t.weights.push_back(c.weight);
        t.alignment.push_back(c.alignment);
    }
    return t;
}

const QFont& PageFlow::tableFont(const ReportTable& t, bool bold) const {
    if (t.compact) return bold ? fonts_.figureBold : fonts_.figure;
    return bold ? fonts_.tableBold : fonts_.table;
}

double PageFlow::tableRowHeight(const ReportTable& t, const QStringList& cells, const std::vector<double>& widths,
                                bool bold) const {
    const QFont& f = tableFont(t, bold);
    size_t lines = 1;
    for (int c = 0; c < cells.size() && size_t(c) < widths.size(); ++c)
        lines = std::max(lines, wrap(cells[c], f, widths[size_t(c)] - 2 * mm(kCellPadMm)).size());
    return double(lines) * lineHeight(f) + 2 * mm(t.compact ? 0.5 : 0.9);
}

void PageFlow::tableRow(const ReportTable& t, const QStringList& cells, const std::vector<double>& widths, bool header,
                        bool bold, bool shaded) {
    const QFont& f = tableFont(t, header || bold);
    const double h = tableRowHeight(t, cells, widths, header || bold);
    const double pad = mm(t.compact ? 0.5 : 0.9), y0 = y_;
    if (header || shaded) {
        const QColor fill = header ? QColor(225, 228, 233) : QColor(245, 246, 248);
        const QRectF band(left_, y0, width(), h);
        add([band, fill](QPainter& p) { p.fillRect(band, fill); });
    }
    double x = left_;
    for (int c = 0; c < cells.size() && size_t(c) < widths.size(); ++c) {
        const double w = widths[size_t(c)];
        const Qt::Alignment a = size_t(c) < t.alignment.size() ? t.alignment[size_t(c)] : Qt::AlignLeft;
        double baseline = y0 + pad + ascent(f);
        for (const QString& line : wrap(cells[c], f, w - 2 * mm(kCellPadMm))) {
            textLine(line, f, x + mm(kCellPadMm), baseline, a, w - 2 * mm(kCellPadMm));
            baseline += lineHeight(f);
        }
        x += w;
    }
    const double l = left_, r = right_, y1 = y0 + h;
    const double pen = mm(header ? 0.25 : 0.1);
    add([l, r, y1, pen](QPainter& p) {
        p.setPen(QPen(QColor(150, 150, 150), pen));
        p.drawLine(QPointF(l, y1), QPointF(r, y1));
    });
    y_ += h;
}

std::vector<double> PageFlow::columnWidths(const ReportTable& t) const {
    const size_t columns = size_t(t.header.size());
    double sum = 0;
    for (size_t c = 0; c < columns; ++c) sum += c < t.weights.size() ? t.weights[c] : 1.0;
    std::vector<double> widths;
    for (size_t c = 0; c < columns; ++c) widths.push_back(width() * (c < t.weights.size() ? t.weights[c] : 1.0) / sum);
    return widths;
}

double PageFlow::tableHeight(const ReportTable& t) const {
    const std::vector<double> widths = columnWidths(t);
    double h = tableRowHeight(t, t.header, widths, true);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const bool bold = std::find(t.boldRows.begin(), t.boldRows.end(), int(r)) != t.boldRows.end();
        h += tableRowHeight(t, t.rows[r], widths, bold);
    }
    return h;
}

double PageFlow::subheadingHeight() const { return lineHeight(fonts_.subheading) + mm(3); }

void PageFlow::table(const ReportTable& t) {
    const std::vector<double> widths = columnWidths(t);
    const double whole = tableHeight(t);
    const double headerHeight = tableRowHeight(t, t.header, widths, true);
    const double first = t.rows.empty() ? 0 : tableRowHeight(t, t.rows.front(), widths, false);
    ensure(whole <= pageHeight() ? whole : headerHeight + first);
    tableRow(t, t.header, widths, true, true, false);
    for (size_t r = 0; r < t.rows.size(); ++r) {
        const bool bold = std::find(t.boldRows.begin(), t.boldRows.end(), int(r)) != t.boldRows.end();
        const double h = tableRowHeight(t, t.rows[r], widths, bold);
        if (y_ + h > bottom_) {
            newPage();
            // The title and the header again: a continuation page says what its rows are.
            if (!t.continuedTitle.isEmpty()) paragraph(t.continuedTitle, fonts_.bodyBold);
            tableRow(t, t.header, widths, true, true, false);
        }
        tableRow(t, t.rows[r], widths, false, bold, r % 2 == 1);
    }
    y_ += mm(2.5);
}

void PageFlow::figure(double height, std::function<void(QPainter&, const QRectF&)> paint) {
    height = std::min(height, bottom_ - top_);
    ensure(height);
    const QRectF area(left_, y_, width(), height);
    add([area, paint = std::move(paint)](QPainter& p) {
        p.save();
        p.setClipRect(area);  // a figure never draws beyond its rectangle
        paint(p, area);
        p.restore();
    });
    y_ += height + mm(2);
}

void PageFlow::paint(QPainter& painter, const QString& header, const QString& headerRight, const QString& footer,
                     const std::function<void()>& nextPage) const {
    const int n = int(pages_.size());
    const QFont small = fonts_.small;
    const QFontMetricsF fm(small, &device_);
    for (int i = 0; i < n; ++i) {
        if (i > 0) nextPage();
        for (const Op& op : pages_[size_t(i)]) op(painter);
        painter.setFont(small);
        painter.setPen(QColor(80, 80, 80));
        // Header: the project on the left, what this is on the right, a rule under both.
        const double headerBase = mm(kHeaderMm);
        const double half = width() / 2 - mm(2);
        painter.drawText(QPointF(left_, headerBase), fm.elidedText(header, Qt::ElideRight, half));
        const QString hr = fm.elidedText(headerRight, Qt::ElideRight, half);
        painter.drawText(QPointF(right_ - fm.horizontalAdvance(hr), headerBase), hr);
        painter.setPen(QPen(QColor(150, 150, 150), mm(0.2)));
        painter.drawLine(QPointF(left_, headerBase + mm(1.8)), QPointF(right_, headerBase + mm(1.8)));
        // Footer: the scene, date and software on the left, "Page n of N" on the right.
        const double footerBase = pageHeight_ - mm(kFooterMm);
        painter.drawLine(QPointF(left_, footerBase - fm.ascent() - mm(1.8)), QPointF(right_, footerBase - fm.ascent() - mm(1.8)));
        painter.setPen(QColor(80, 80, 80));
        const QString page = QStringLiteral("Page %1 of %2").arg(i + 1).arg(n);
        const double pageWidth = fm.horizontalAdvance(page);
        painter.drawText(QPointF(left_, footerBase), fm.elidedText(footer, Qt::ElideMiddle, width() - pageWidth - mm(5)));
        painter.drawText(QPointF(right_ - pageWidth, footerBase), page);
    }
}

}  // namespace lucerna
