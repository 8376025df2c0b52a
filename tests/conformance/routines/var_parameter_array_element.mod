MODULE var_parameter_array_element
  ! Tests: an array element may be passed to a VAR parameter; the element
  ! itself is updated (by reference), its neighbours are not.
  PROC bump(VAR num v)
    v := v + 1;
  ENDPROC
  PROC main()
    VAR num a{3} := [10, 20, 30];
    VAR num i := 2;
    bump a{i};
    bump a{i};
    bump a{3};
    TPWrite "a{1}=" \Num:=a{1};
    TPWrite "a{2}=" \Num:=a{2};
    TPWrite "a{3}=" \Num:=a{3};
  ENDPROC
ENDMODULE
