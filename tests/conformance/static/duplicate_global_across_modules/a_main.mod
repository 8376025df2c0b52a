MODULE a_main
  ! Tests: global names must be unique across all modules of a task: a
  ! global VAR declared in two modules is a duplicate (RMC204).
  VAR num total := 0;
  PROC main()
    TPWrite "never printed";
  ENDPROC
ENDMODULE
