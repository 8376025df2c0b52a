MODULE goto_label_in_other_routine
  ! Tests: labels are visible only in their own routine: GOTO to a label of
  ! another routine is an unknown label (RMC212).
  PROC other()
  target:
    TPWrite "other";
  ENDPROC
  PROC main()
    TPWrite "never printed";
    GOTO target;  ! <-- error
  ENDPROC
ENDMODULE
