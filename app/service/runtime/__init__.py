"""What runs the work: the worker pool, cores and gates, fair shares, memory, caches and progress."""
