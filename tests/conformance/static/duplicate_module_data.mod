MODULE duplicate_module_data
  ! Tests: two declarations of one name in one module are a static error
  ! (duplicate, RMC204).
  VAR num speed := 1;
  VAR num speed := 2;  ! <-- error
  PROC main()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
