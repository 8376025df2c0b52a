MODULE late_binding_string_variable
  ! Tests: late binding %expr% calls the procedure whose name is the string
  ! value at run time; name matching ignores case.
  PROC greet()
    TPWrite "hello";
  ENDPROC
  PROC wave()
    TPWrite "waving";
  ENDPROC
  PROC main()
    VAR string name := "greet";
    %name%;
    name := "WAVE";
    %name%;
  ENDPROC
ENDMODULE
