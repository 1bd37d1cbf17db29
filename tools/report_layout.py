"""The page layout of out/report.pdf: Layout places text, figures, legends and tables on A4
pages from the top, measuring text with the renderer, continuing on a new page whatever does
not fit, and checks each page's text blocks and axes against each other and the page's edges
before saving it (an overlap goes to Layout.problems, which tools/report.py prints on stderr).

Also the page's measures (A4, the margins), INK (the report's blue) and plain_log_ticks, the
log axis labelled 0.3, 1, 3, 10 that the spectrum and fragility pages share.  Importing this
module selects matplotlib's Agg backend (no display is needed) and the report's font.

The font: DejaVu Sans (shipped with matplotlib, so always found) embedded as TrueType
(pdf.fonttype 42) with its Unicode map, so that a reader can search and copy the text.
matplotlib's default, Type 3, draws every glyph beyond Latin-1 (θ, α, ω, ≥, −, ⁻¹) as a
picture that pdftotext and a viewer's search do not see (issue 40).  The prose, tables and
axis labels write Greek as Unicode characters, never as mathtext ($\\alpha$): _place
escapes "$", so no paragraph is parsed as mathtext; only the log axes' 10^n tick labels are
matplotlib's mathtext, set in the same DejaVu Sans.
"""
import matplotlib
matplotlib.use("Agg")
matplotlib.rcParams.update({"pdf.fonttype": 42, "font.family": "DejaVu Sans", "mathtext.fontset": "dejavusans"})
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.font_manager import FontProperties  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402
from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter  # noqa: E402

A4 = (8.27, 11.69)          # inches
LEFT, RIGHT, TOP, BOTTOM = 0.6, 0.6, 0.45, 0.45   # page margins, inches
INK = "#1f3a5f"


class Layout:
    """Pages laid out from the top by measured text and requested figure heights."""

    def __init__(self, pdf):
        self.pdf = pdf
        self.fig = None
        self.pages = 0
        self.problems = []
        self._line_h = {}

    # --- pages ---------------------------------------------------------------------
    def page(self, title, compares):
        """A new page: its title and the sentence saying what it compares."""
        self.finish()
        self.title, self.compares = title, compares
        self._open(continued=False)

    def _open(self, continued):
        self.fresh = True
        self.fig = plt.figure(figsize=A4)
        self.renderer = self.fig.canvas.get_renderer()
        self.dpi = self.fig.dpi
        self.W, self.H = A4
        self.width = self.W - LEFT - RIGHT
        self.y = TOP
        self.artists, self.axes = [], []
        self.pages += 1
        self.text(self.title + (" (continued)" if continued else ""), 14, weight="bold", gap=0.08, split=False)
        self.text(self.compares, 9, style="italic", color=INK, gap=0.14, split=False)
        self.fresh = True       # nothing but the header yet: never worth a new page

    def section(self, title, compares, room=1.5):
        """A page's worth of title and sentence at the cursor, for a section too short to deserve a
        page of its own (a note that an output is missing): a new page only when less than `room`
        inches would remain below them.  Its continuation pages carry its title."""
        if self.fig is None or self.room < 0.15 + self.line_height(12)[1] + 2 * self.line_height(9)[0] + room:
            self.page(title, compares)
            return
        self.y += 0.15
        self.title, self.compares = title, compares
        self.text(title, 12, weight="bold", gap=0.06, split=False)
        self.text(compares, 9, style="italic", color=INK, gap=0.12, split=False)

    def continue_page(self):
        self.finish()
        self._open(continued=True)

    @property
    def room(self):
        return self.H - BOTTOM - self.y

    def need(self, inches):
        """Start a continuation page unless `inches` remain on this one."""
        if self.room < inches and not self.fresh:
            self.continue_page()

    # --- text ----------------------------------------------------------------------
    def _prop(self, size, weight="normal", style="normal"):
        return FontProperties(size=size, weight=weight, style=style)

    def _width(self, s, prop):
        return self.renderer.get_text_width_height_descent(s, prop, ismath=False)[0] / self.dpi

    def wrap(self, s, size, width, weight="normal", style="normal"):
        """Lines of s no wider than `width` inches, measured in the page's font."""
        prop = self._prop(size, weight, style)
        limit = width * 0.985
        lines = []
        for para in s.split("\n"):
            cur = ""
            for word in para.split(" "):
                while self._width(word, prop) > limit:      # a word longer than the line
                    k = len(word)
                    while k > 1 and self._width(word[:k], prop) > limit:
                        k -= 1
                    if cur:
                        lines.append(cur)
                        cur = ""
                    lines.append(word[:k])
                    word = word[k:]
                cand = f"{cur} {word}" if cur else word
                if not cur or self._width(cand, prop) <= limit:
                    cur = cand
                else:
                    lines.append(cur)
                    cur = word
            lines.append(cur)
        return lines

    def line_height(self, size):
        if size not in self._line_h:
            t1 = self.fig.text(0, 0, "Ag", fontsize=size)
            t2 = self.fig.text(0, 0, "Ag\nAg", fontsize=size)
            h1 = t1.get_window_extent(self.renderer).height / self.dpi
            h2 = t2.get_window_extent(self.renderer).height / self.dpi
            t1.remove()
            t2.remove()
            self._line_h[size] = (h2 - h1, h1)
        return self._line_h[size]

    def _place(self, x, y, s, size, **kw):
        t = self.fig.text(x / self.W, 1 - y / self.H, s.replace("$", r"\$"), fontsize=size, va="top", ha="left", **kw)
        self.artists.append(t)
        self.fresh = False
        return t, t.get_window_extent(self.renderer).height / self.dpi

    def text(self, s, size=8, indent=0.0, gap=0.06, split=True, weight="normal", style="normal", color="black"):
        """A paragraph at the cursor, wrapped to the page; what does not fit goes on."""
        lines = self.wrap(s, size, self.width - indent, weight, style)
        self.split_started = False
        step, first = self.line_height(size)
        while lines:
            fit = 1 + int(max(0.0, self.room - first) / step) if self.room >= first else 0
            # A short paragraph stays whole, a long one leaves at least two lines behind.
            whole = not split or (len(lines) <= 4 and not self.split_started)
            fresh = self.fresh
            if (fit < len(lines) if whole else fit < min(len(lines), 2)) and not fresh:
                self.continue_page()
                continue
            n = len(lines) if whole else max(1, min(len(lines), fit))
            while True:              # the estimate checked by measuring what was placed
                t, h = self._place(LEFT + indent, self.y, "\n".join(lines[:n]), size,
                                   weight=weight, style=style, color=color)
                if self.y + h <= self.H - BOTTOM + 1e-3 or (fresh and n == 1):
                    break
                t.remove()
                self.artists.pop()
                if n == 1 or (whole and not fresh):
                    n = 0
                    break
                n -= 1
            if n == 0:
                self.fresh = fresh
                self.continue_page()
                continue
            self.y += h
            lines = lines[n:]
            if lines:
                self.split_started = True
                self.continue_page()
        self.y += gap

    # --- figures ---------------------------------------------------------------------
    def figure(self, height, draw, gap=0.12):
        """`height` inches for draw(layout, (x, y, w, h)) at the cursor, on this page or the next."""
        if self.room < height:
            self.continue_page()
            height = min(height, self.room)
        draw(self, (LEFT, self.y, self.width, height))
        self.fresh = False
        self.y += height + gap

    def grid(self, rect, rows, cols, pad_l=0.62, pad_r=0.12, pad_t=0.3, pad_b=0.5, **kw):
        """rows x cols axes in rect (inches from the top-left), each cell leaving room for its
        tick labels, axis labels and title inside the cell."""
        x, y, w, h = rect
        cw, ch = w / cols, h / rows
        out = []
        for r in range(rows):
            for c in range(cols):
                left = x + c * cw + pad_l
                top = y + r * ch + pad_t
                aw, ah = cw - pad_l - pad_r, ch - pad_t - pad_b
                ax = self.fig.add_axes([left / self.W, 1 - (top + ah) / self.H, aw / self.W, ah / self.H], **kw)
                self.axes.append(ax)
                out.append(ax)
        return out

    def legend(self, handles, labels, rect, height, ncol):
        """A legend for the whole figure in the strip of `height` inches at the bottom of rect."""
        x, y, w, h = rect
        leg = self.fig.legend(handles, labels, loc="center", ncol=ncol, fontsize=7, frameon=False,
                              bbox_to_anchor=((x + w / 2) / self.W, 1 - (y + h - height / 2) / self.H))
        self.artists.append(leg)
        return leg

    # --- tables ----------------------------------------------------------------------
    def table(self, header, rows, widths, size=7, pad=0.035):
        """A table at the cursor; columns in proportion to `widths`, cells wrapped by
        measurement, every row as tall as its tallest cell; the header is repeated on
        each page the table runs onto."""
        total = float(sum(widths))
        cw = [self.width * w / total for w in widths]
        step, first = self.line_height(size)

        def cells(r, weight):
            return [self.wrap(str(c), size, w - 2 * pad, weight) for c, w in zip(r, cw)]

        def height(cl):
            n = max(len(c) for c in cl)
            return first + (n - 1) * step + 2 * pad

        head = cells(header, "bold")

        def draw_row(cl, weight, shade):
            h = height(cl)
            if shade:
                self.fig.add_artist(Rectangle((LEFT / self.W, 1 - (self.y + h) / self.H), self.width / self.W,
                                              h / self.H, transform=self.fig.transFigure, color=shade, lw=0, zorder=0))
            x = LEFT
            for c, w in zip(cl, cw):
                if any(c):
                    self._place(x + pad, self.y + pad, "\n".join(c), size, weight=weight)
                x += w
            self.y += h
            self.fig.add_artist(Line2D([LEFT / self.W, (LEFT + self.width) / self.W], [1 - self.y / self.H] * 2,
                                       transform=self.fig.transFigure, lw=0.4, color="#999999"))

        if self.room < height(head) + (height(cells(rows[0], "normal")) if rows else 0):
            self.continue_page()
        draw_row(head, "bold", "#e8e8e8")
        for r in rows:
            cl = cells(r, "normal")
            if self.room < height(cl):
                self.continue_page()
                draw_row(head, "bold", "#e8e8e8")
            draw_row(cl, "normal", None)
        self.y += 0.12

    # --- the check and the page's end ------------------------------------------------------
    def finish(self):
        if self.fig is None:
            return
        r = self.renderer
        boxes = [(f"{type(t).__name__.lower()} '{t.get_text()[:40] if hasattr(t, 'get_text') else ''}'",
                  t.get_window_extent(r)) for t in self.artists]
        boxes += [(f"axes '{ax.get_title()[:30] or i}'", ax.get_tightbbox(r)) for i, ax in enumerate(self.axes)]
        W, H = self.W * self.dpi, self.H * self.dpi
        where = f"page {self.pages} ({self.title})"
        for name, b in boxes:
            if b.x0 < -1 or b.y0 < -1 or b.x1 > W + 1 or b.y1 > H + 1:
                self.problems.append(f"{where}: {name} runs off the page")
        for i in range(len(boxes)):
            for j in range(i + 1, len(boxes)):
                a, b = boxes[i][1], boxes[j][1]
                if min(a.x1, b.x1) - max(a.x0, b.x0) > 1 and min(a.y1, b.y1) - max(a.y0, b.y0) > 1:
                    self.problems.append(f"{where}: {boxes[i][0]} overlaps {boxes[j][0]}")
        self.pdf.savefig(self.fig)
        plt.close(self.fig)
        self.fig = None


def plain_log_ticks(ax):
    """A log x axis labelled 0.3, 1, 3, 10, 30 rather than in powers of ten."""
    ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 3.0)))
    ax.xaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax.xaxis.set_minor_formatter(NullFormatter())
