MODULE MainModule
  ! Tests: TPReadNum stores into its first argument, so that must be a data reference.
  PROC main()
    TPWrite "must not run";
    TPReadNum 5, "How many?";
  ENDPROC
ENDMODULE
