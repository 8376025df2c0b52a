MODULE Weld
    ! Written for the test (issue 28, the taeyangshim TASK9 rows): the robot task numbers
    ! its weld steps and sets 0 when it is done.
    PERS num nStep{2} := [0,0];

    PROC main()
        nStep{1} := 1;
        nStep{1} := 2;
        nStep{1} := 0;
    ENDPROC
ENDMODULE
