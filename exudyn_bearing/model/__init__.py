"""The Exudyn model of a bearing: the builder (``CreateAngularContactBearing``), the bearing
connector and its compiled path, the step rule and the Newton predictor it installs."""
