MODULE Robot
    ! Written for the test (issue 27): the robot task reports -1 on a fault, 1 when done.
    PERS num nCode := 0;

    PROC main()
        nCode := 1;
        nCode := -1;
    ENDPROC
ENDMODULE
