MODULE uncaught_outofbnd_in_function
  ! Tests: an error inside a function called from an expression, handled
  ! nowhere, stops the program (exit 1); the statement using the result
  ! prints nothing.
  VAR num table{2} := [1, 2];
  FUNC num get(num i)
    RETURN table{i};
  ENDFUNC
  PROC main()
    TPWrite "get(1)=" \Num:=get(1);
    TPWrite "get(0)=" \Num:=get(0);
  ENDPROC
ENDMODULE
