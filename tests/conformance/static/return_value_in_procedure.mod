MODULE return_value_in_procedure
  ! Tests: RETURN with a value is allowed only in a FUNC; in a PROC it is a
  ! static error (the code is not pinned, only exit code and position).
  PROC main()
    TPWrite "never printed";
    RETURN 5;  ! <-- error
  ENDPROC
ENDMODULE
