# Open the output of one figure: pngcairo for 'out' ending in .png, pdfcairo for .pdf.
# fig_w, fig_h: size in pixels of the PNG; the PDF gets the same shape at 200 pixels per inch
# (a pair of panels is 9 inches wide), with a 7 pt font.
if (!exists("out")) {
    exit error "no output file given: add out='figure.png' (or .pdf) to gnuplot -e"
}
_ext = strlen(out) > 4 ? out[strlen(out) - 3:] : ""
if (_ext eq ".pdf") {
    set terminal pdfcairo noenhanced color size (fig_w / 200.0), (fig_h / 200.0) font "Sans,7" linewidth 0.6 pointscale 0.5
} else {
    if (_ext eq ".png") {
        set terminal pngcairo noenhanced color size fig_w, fig_h font "Sans,11" linewidth 1
    } else {
        exit error sprintf("out='%s': the file name must end in .png or .pdf", out)
    }
}
set output out
