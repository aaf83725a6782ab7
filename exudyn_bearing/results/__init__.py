"""What a run leaves: outputs recomputed from the recorded states, result records (units,
inputs, assumptions), plots and renderer graphics."""
