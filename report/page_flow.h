#pragma once
// The pages of a report, laid out before any is painted (so that the footer can say "page n of
// N"): A4 portrait with margins, a header and a footer on every page, and a cursor that flows
// headings, wrapped paragraphs, tables and figures down the page, starting a new page where the
// next item does not fit. Text wraps at word boundaries (anywhere within a word longer than
// the line), tables split between rows and repeat their header row, so nothing runs off a page.
// Lengths are in the device's pixels; mm() converts.

#include <QFont>
#include <QString>
#include <QStringList>

#include <functional>
#include <vector>

class QPainter;
class QPaintDevice;
class QRectF;

namespace lucerna {

struct ReportFonts {
    QFont title, subtitle, heading, subheading, body, bodyBold, small, table, tableBold, figure, figureBold;
};

// A table's columns share the content width in proportion to `weights`; cells wrap.
struct ReportTable {
    QStringList header;
    std::vector<QStringList> rows;
    std::vector<double> weights;          // one per column
    std::vector<Qt::Alignment> alignment; // one per column (left when absent)
    std::vector<int> boldRows;            // rows set in bold (a total)
    bool compact = false;                 // the small font (tables of values)
    // A table split between pages: this line, when given, above the repeated header row on
    // each page it continues onto ("desk: illuminance at the grid points [lx] (continued)").
    QString continuedTitle;
};

// A column of a table: its heading, its share of the width and how its cells align.
struct ReportColumn {
    QString header;
    double weight = 1;
    Qt::Alignment alignment = Qt::AlignLeft;
};
// A table of these columns, without rows yet.
ReportTable tableOf(const std::vector<ReportColumn>& columns);

class PageFlow {
public:
    // `device` is what will be painted (a QPdfWriter set to A4 portrait): fonts are measured on it.
    explicit PageFlow(QPaintDevice& device);

    double mm(double millimetres) const;
    const ReportFonts& fonts() const { return fonts_; }
    // The area between the margins, below the header and above the footer.
    double left() const { return left_; }
    double right() const { return right_; }
    double width() const { return right_ - left_; }
    double top() const { return top_; }
    double bottom() const { return bottom_; }
    double y() const { return y_; }
    double remaining() const { return bottom_ - y_; }

    void newPage();
    // Starts a new page unless `height` fits below the cursor.
    void ensure(double height);
    void space(double height);

    void title(const QString& text, const QFont& font);
    void heading(const QString& text);
    void subheading(const QString& text);
    // Wrapped to the content width (or `indent` in from the left), split between pages line by
    // line; "\n" starts a new line.
    void paragraph(const QString& text, const QFont& font, double indent = 0);
    void paragraph(const QString& text) { paragraph(text, fonts_.body); }
    // "Key" and "value" pairs: keys in a column of `keyShare` of the width, values wrapped.
    void keyValues(const std::vector<std::pair<QString, QString>>& pairs, double keyShare = 0.3);
    // A table that fits on a page is kept whole (a new page when it does not fit below the
    // cursor); a longer one splits between rows, each page after the first starting with its
    // continuedTitle (if any) and its header row.
    void table(const ReportTable& table);
    double tableHeight(const ReportTable& table) const;
    double pageHeight() const { return bottom_ - top_; }
    double subheadingHeight() const;
    // A figure `height` tall across the content width, kept whole on one page: `paint` draws it
    // within the rectangle it is given.
    void figure(double height, std::function<void(QPainter&, const QRectF&)> paint);

    int pageCount() const { return int(pages_.size()); }
    // Paints every page, `header` on its left and the page number on the right of its footer
    // beside `footer`; calls newPage() on the device between pages (`nextPage`).
    void paint(QPainter& painter, const QString& header, const QString& headerRight, const QString& footer,
               const std::function<void()>& nextPage) const;

    // The lines `text` wraps into at `width` with `font`.
    std::vector<QString> wrap(const QString& text, const QFont& font, double width) const;
    double lineHeight(const QFont& font) const;

private:
    using Op = std::function<void(QPainter&)>;
    void add(Op op);
    void textLine(const QString& text, const QFont& font, double x, double baseline, Qt::Alignment alignment = Qt::AlignLeft,
                  double width = 0);
    double ascent(const QFont& font) const;
    double tableRowHeight(const ReportTable& t, const QStringList& cells, const std::vector<double>& widths, bool bold) const;
    std::vector<double> columnWidths(const ReportTable& t) const;
    const QFont& tableFont(const ReportTable& t, bool bold) const;
    void tableRow(const ReportTable& t, const QStringList& cells, const std::vector<double>& widths, bool header,
                  bool bold, bool shaded);

    QPaintDevice& device_;
    ReportFonts fonts_;
    double dpmm_;  // device pixels per millimetre
    double left_, right_, top_, bottom_, pageWidth_, pageHeight_;
    double y_ = 0;
    std::vector<std::vector<Op>> pages_;
};

}  // namespace lucerna
