MODULE assign_to_const
  ! Tests: assignment to a CONST is a static error (RMC207).
  CONST num LIMIT := 10;
  PROC main()
    TPWrite "never printed";
    LIMIT := 11;  ! <-- error
  ENDPROC
ENDMODULE
