MODULE goto_unknown_label
  ! Tests: GOTO to a label that does not exist in the routine is a static
  ! error (RMC212).
  PROC main()
    TPWrite "never printed";
    GOTO nowhere;  ! <-- error
  ENDPROC
ENDMODULE
