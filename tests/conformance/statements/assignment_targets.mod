MODULE assignment_targets
  ! Tests: assignment to entire variables, array elements, record components
  ! and components of array elements; the right side is evaluated before
  ! the target is written (x := x + 1).
  VAR pos pts{2};
  PROC main()
    VAR num x := 1;
    VAR num a{3};
    VAR pos p;
    x := x + 1;
    a{x} := 7;
    p.y := a{2} * 2;
    pts{x}.z := p.y + x;
    TPWrite "x=" \Num:=x;
    TPWrite "a{2}=" \Num:=a{2};
    TPWrite "p=" \Pos:=p;
    TPWrite "pts{2}=" \Pos:=pts{2};
  ENDPROC
ENDMODULE
