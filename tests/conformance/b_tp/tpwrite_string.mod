MODULE MainModule
  ! Tests: TPWrite prints its string followed by a newline; "" prints an empty line; the
  ! string may be any string expression.
  PROC main()
    VAR string name := "rapid";
    TPWrite "Hello";
    TPWrite "";
    TPWrite "name: " + name;
    TPWrite "quote "" and backslash \\";
  ENDPROC
ENDMODULE
