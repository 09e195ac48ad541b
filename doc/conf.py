# Sphinx configuration of the manual. Build it with scripts/build_manual.sh,
# which copies doc/ into the build folder, generates the parameter reference
# from the programs into reference/, and runs Sphinx with warnings as errors.
project = "mpm"
author = "the mpm developers"
copyright = "the mpm developers"

extensions = ["myst_parser"]
source_suffix = {".md": "markdown"}
myst_enable_extensions = ["dollarmath", "amsmath"]
# anchors for headings of levels 1 to 3, so pages can link to sections
myst_heading_anchors = 3

exclude_patterns = ["_build", "figures/*.py"]
html_theme = "alabaster"
html_theme_options = {"page_width": "1100px", "sidebar_width": "260px"}
html_title = "mpm manual"
html_show_sourcelink = False
