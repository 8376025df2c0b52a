MODULE outofbnd_in_function_handler
  ! Tests: ERR_OUTOFBND raised while reading an array element inside a FUNC
  ! is handled there, returning a fallback value.
  VAR num table{3} := [10, 20, 30];
  FUNC num lookup(num i)
    RETURN table{i};
  ERROR
    IF ERRNO = ERR_OUTOFBND RETURN -1;
  ENDFUNC
  PROC main()
    TPWrite "lookup(2)=" \Num:=lookup(2);
    TPWrite "lookup(4)=" \Num:=lookup(4);
  ENDPROC
ENDMODULE
