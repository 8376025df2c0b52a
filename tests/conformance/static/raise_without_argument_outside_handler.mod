MODULE raise_outside_handler
  ! Tests: RAISE without an error number is allowed only in an ERROR handler
  ! (statement in a place RAPID does not allow, RMC210).
  PROC main()
    TPWrite "never printed";
    RAISE;  ! <-- error
  ENDPROC
ENDMODULE
