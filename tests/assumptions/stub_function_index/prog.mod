MODULE StubIndex
    ! The slot comes from a routine of a library that is not given (GetSlot); its stub
    ! returns the neutral 0, and slots{0} is out of bounds. The violation rests on the
    ! stub: the verdict line says so. OpenGripper, also a stub, is not on the path.
    VAR num slots{4} := [1, 2, 3, 4];
    VAR num picked := 0;

    PROC main()
        picked := slots{GetSlot()};
        OpenGripper;
    ENDPROC
ENDMODULE
