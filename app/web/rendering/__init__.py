"""What pages are rendered with: the templates, MathML, prose, the embed views, the page cache."""
