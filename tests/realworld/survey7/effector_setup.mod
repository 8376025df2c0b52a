MODULE effector_setup
    ! Survey round 7: a record of another module (not given) holds the tool of the
    ! end effector; its frame is turned through nested components before the whole
    ! component is copied into a tooldata. The stubs must declare the component as a
    ! tooldata, not as records invented for .tframe and .tframe.rot.
    LOCAL PERS tooldata tActive := [TRUE,[[0,0,0],[1,0,0,0]],[0.5,[0,0,10],[1,0,0,0],0,0,0]];
    PERS num nTurned := 0;

    PROC main()
        VAR effector_t ee;
        ee.grip := [TRUE,[[0,0,120],[1,0,0,0]],[1.2,[0,0,40],[1,0,0,0],0,0,0]];
        ee.grip.tframe.rot := OrientZYX(90, 0, 0);
        ee.grip.tframe.trans.z := 125;
        tActive := ee.grip;
        IF tActive.tframe.trans.z = 125 nTurned := nTurned + 1;
        ApproachWith ee, 50;
    ENDPROC
ENDMODULE
