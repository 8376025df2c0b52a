MODULE const_to_var_parameter
  ! Tests: a CONST cannot be passed to a VAR parameter (compile error per
  ! reference 4.2); the diagnostic code (read-only or not-a-reference) is
  ! not pinned, only the exit code and the position.
  CONST num LIMIT := 3;
  PROC bump(VAR num v)
    v := v + 1;
  ENDPROC
  PROC main()
    TPWrite "never printed";
    bump LIMIT;  ! <-- error
  ENDPROC
ENDMODULE
