MODULE retry_outside_handler
  ! Tests: RETRY is allowed only in an ERROR handler (RMC210).
  PROC main()
    TPWrite "never printed";
    RETRY;  ! <-- error
  ENDPROC
ENDMODULE
