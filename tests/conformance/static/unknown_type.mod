MODULE unknown_type
  ! Tests: declaring data of an undeclared type is a static error (unknown
  ! type, RMC202).
  VAR widget w;  ! <-- error
  PROC main()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
