MODULE declaration_order_any
  ! Tests: a routine may call routines declared later in the same module:
  ! routine names are visible in the whole module, whatever their order.
  VAR num calls := 0;
  PROC main()
    first;
    TPWrite "calls=" \Num:=calls;
  ENDPROC
  PROC first()
    calls := calls + 1;
    second;
  ENDPROC
  PROC second()
    calls := calls + 10;
  ENDPROC
ENDMODULE
