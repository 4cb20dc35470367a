"""The autograder: a pytest plugin (``plugin``) and the ``python -m gandalf_core.grading`` front end."""
