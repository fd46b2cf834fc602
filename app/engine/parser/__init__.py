"""From the text a user types to checked SymPy: the parser's gates, the symbol table, a user's system."""
