MODULE unknown_procedure
  ! Tests: a call of an undeclared procedure is a static error (unknown
  ! routine, RMC203).
  PROC main()
    TPWrite "never printed";
    DoesNotExist 1;  ! <-- error
  ENDPROC
ENDMODULE
