MODULE function_calls_in_expressions
  ! Tests: user function calls are operands like any other: sq(3) + sq(4),
  ! nested calls, and calls inside array indices.
  VAR num table{5} := [10, 20, 30, 40, 50];
  FUNC num sq(num v)
    RETURN v * v;
  ENDFUNC
  PROC main()
    TPWrite "sum=" \Num:=sq(3) + sq(4);
    TPWrite "nested=" \Num:=sq(sq(2));
    TPWrite "index=" \Num:=table{sq(2)};
  ENDPROC
ENDMODULE
