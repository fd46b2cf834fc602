"""The step checker as a service: problems built in the pool, answers judged and typeset."""
