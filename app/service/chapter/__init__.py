"""The chapter's scenes as a process serves them: derivations, documents, compiled systems."""
