MODULE assign_string_to_num
  ! Tests: assigning a string to a num variable is a type mismatch (RMC206).
  PROC main()
    VAR num n;
    TPWrite "never printed";
    n := "five";  ! <-- error
  ENDPROC
ENDMODULE
