"""The HTML pages: the chapter, the playground, the classes' pages, the embeds."""
