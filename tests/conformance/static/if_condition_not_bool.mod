MODULE if_condition_not_bool
  ! Tests: an IF condition must be bool; a num condition is a type mismatch
  ! (no numeric truthiness in RAPID, RMC206).
  PROC main()
    VAR num n := 1;
    TPWrite "never printed";
    IF n THEN  ! <-- error
      TPWrite "n";
    ENDIF
  ENDPROC
ENDMODULE
