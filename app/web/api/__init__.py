"""The JSON API's routes, their dependencies, errors, body limits and the OpenAPI document."""
