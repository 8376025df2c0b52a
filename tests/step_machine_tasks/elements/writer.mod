! Task 1: writes of array elements by a computed index (the machine makes the array with
! the element): from a constant, from global data, from an expression, from an aggregate
! it computes; the index out of range while the other task's phase is 2 (ERR_OUTOFBND:
! the machine's check fails and Python raises); components of elements, one and two
! records deep (the machine rebuilds the element along the path; one whose value reads
! an element's component is Python's).
MODULE Writer
  CONST robtarget home := [[500,0,600],[0,0,1,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
  VAR robtarget targets{3};
  VAR num counts{40};
  VAR num n := 0;
  VAR speeddata speed := [100,500,5000,1000];
  VAR speeddata speeds{3};
  VAR jointtarget joints{3};
  PERS num phase := 0;
  PROC main()
    WHILE TRUE DO
      n := n MOD 3 + 1;
      targets{n} := home;
      speeds{n} := speed;
      joints{n} := [[n,0,0,0,30 + phase,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
      counts{n * 10} := n MOD 2 + phase;
      IF phase = 2 counts{n + 40} := 1;
      targets{n}.trans.x := 400 + n;
      speeds{n}.v_ori := 200 + phase;
      speeds{n}.v_leax := speeds{n}.v_leax + phase;
    ENDWHILE
  ENDPROC
ENDMODULE
