"""The step checker: a student's answer read, compared with the derivation, its mistake named."""
