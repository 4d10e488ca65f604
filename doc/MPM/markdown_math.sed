# Doxygen input filter of the Markdown pages (FILTER_PATTERNS in Doxyfile):
# inline math written \( ... \), as MathJax and most Markdown renderers read
# it, becomes Doxygen's \f$ ... \f$, which Doxygen 1.9 hands to MathJax.
s/\\(/\\f$/g
s/\\)/\\f$/g
