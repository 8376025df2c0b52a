MODULE RecipeCell
  ! Issue 19: the program writes aggregates to data of a module not given. Their sizes and
  ! component counts come from the aggregates (not from an index or an unrelated record):
  ! nHeights{5} not {10}; pOffset a num{3}, no pos guessed; layers a num{2,3}; labels a
  ! string{2,2}, no listitem; recipe a record c1 string, c2 num, c3 bool; station a record
  ! whose read component .name takes the first string place of the value written.
  ! A type named like a predefined non-value type (datapos), declared with a value, is the
  ! program's own type of a module not given: the stubs declare it too.
  PERS datapos dpFeeder := ["feeder", 2];

  PROC main()
    nHeights := [10, 20, 30, 40, 50];
    pOffset := [0, 0, 25];
    layers := [[1, 2, 3], [4, 5, 6]];
    labels := [["top", "a"], ["bottom", "b"]];
    recipe := ["box", 12, TRUE];
    station := ["press", 3];
    TPWrite station.name;
    TPWrite dpFeeder.name;
    TPWrite "height" \Num:=nHeights{2};
    IF recipe.c3 THEN
      TPWrite "layers" \Num:=layers{2, 3};
    ENDIF
  ENDPROC
ENDMODULE
