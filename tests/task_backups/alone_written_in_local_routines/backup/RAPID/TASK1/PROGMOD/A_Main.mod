MODULE A_Main
    ! Written for the test (issue 27): two modules of the robot task each have a LOCAL
    ! routine Mark; this one writes -1.
    PERS num nCode := 0;

    PROC main()
        Mark;
        Finish;
    ENDPROC

    LOCAL PROC Mark()
        nCode := -1;
    ENDPROC
ENDMODULE
