MODULE uncaught_user_error
  ! Tests: a user error (RAISE 42) that nobody handles stops the program
  ! with exit code 1.
  PROC main()
    TPWrite "raising";
    RAISE 42;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
