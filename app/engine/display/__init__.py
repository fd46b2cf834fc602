"""How an expression is printed: names, textbook forms, long formulas broken, running text."""
