"""Plain-text tables for the study scripts' reports (scripts/study_*.py)."""


def print_table(title, head, body, fmts, min_width=7):
    """Print TITLE, then HEAD and the rows of BODY right-aligned, each value by its printf format
    in FMTS; a column is as wide as its heading, at least MIN_WIDTH."""
    print("\n" + title)
    w = [max(len(h), min_width) for h in head]
    print("  ".join(h.rjust(n) for h, n in zip(head, w)))
    print("  ".join("-" * n for n in w))
    for b in body:
        print("  ".join((f % v).rjust(n) for f, v, n in zip(fmts, b, w)))
