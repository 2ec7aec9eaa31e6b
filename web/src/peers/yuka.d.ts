// The few names of Yuka 0.7.8 (npm `yuka`, JavaScript game AI) the peers
// code uses: the package ships no types. Yuka works in 3D with y up; the
// peers code moves its vehicles in the x–z plane (our y is Yuka's z).
declare module "yuka" {
  export class Vector3 {
    x: number;
    y: number;
    z: number;
    constructor(x?: number, y?: number, z?: number);
    set(x: number, y: number, z: number): this;
    length(): number;
  }
  export class SteeringBehavior {
    active: boolean;
    weight: number;
  }
  export class ArriveBehavior extends SteeringBehavior {
    constructor(target?: Vector3, deceleration?: number, tolerance?: number);
    target: Vector3;
    deceleration: number;
    tolerance: number;
  }
  export class SeekBehavior extends SteeringBehavior {
    constructor(target?: Vector3);
    target: Vector3;
  }
  export class SteeringManager {
    add(behavior: SteeringBehavior): this;
  }
  export class Vehicle {
    position: Vector3;
    velocity: Vector3;
    mass: number;
    maxSpeed: number;
    maxForce: number;
    maxTurnRate: number;
    steering: SteeringManager;
    getDirection(result: Vector3): Vector3;
    lookAt(target: Vector3): this;
    update(delta: number): this;
  }
}
