MODULE const_initialised_from_variable
  ! Tests: a CONST initialiser must be a constant expression; naming a VAR
  ! is a static error (RMC213).
  VAR num v := 3;
  CONST num C := v + 1;  ! <-- error
  PROC main()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
