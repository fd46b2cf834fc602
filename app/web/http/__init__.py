"""HTTP itself: addresses, content codings, ETags, security headers, slow clients, lean responses."""
